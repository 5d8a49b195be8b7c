#!/bin/sh
# The compiler launcher of the top-level CMakeLists.txt when ccache is
# installed: one program (a launcher that is a list of words does not
# survive being handed on to another CMake project, as the package tests
# do). pch_defines,time_macros let ccache cache the test programs'
# precompiled header; the source tree as base directory shares the cache
# between clones. CCACHE_DISABLE=1 still turns it off.
root=$(cd "$(dirname "$0")/.." && pwd)
CCACHE_SLOPPINESS=pch_defines,time_macros CCACHE_BASEDIR="$root" exec ccache "$@"
