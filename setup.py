"""Builds the `skelconv` extension module with CMake for pip (docs/python.md).

pyproject.toml names setuptools as the build backend; setuptools calls
build_ext below, which configures the project with the Python module and
the libraries it links only (no tests, generator, verifier, benchmarks or
figures), builds the target skelconv_python for the Python that runs pip,
and copies the module, with the OpenVDB module of the grid mesher that it
opens from beside itself (src/mesh/grid_mesher_loader.cpp), where
setuptools packs it.

The CMake build directory is build/python-package in the source tree, kept
between runs so that a second `pip install` rebuilds only what changed;
SKELCONV_CMAKE_BUILD_DIR sets another. ccache is used when it is on PATH.
CMAKE_BUILD_PARALLEL_LEVEL sets the number of compile jobs (default: the
number of cores).
"""
import os
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


class CMakeExtension(Extension):
    """An extension whose sources CMake compiles (python/CMakeLists.txt)."""

    def __init__(self, name, target):
        super().__init__(name, sources=[])
        self.target = target


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build_dir = Path(os.environ.get("SKELCONV_CMAKE_BUILD_DIR", ROOT / "build" / "python-package"))
        configure = [
            "cmake", "-S", str(ROOT), "-B", str(build_dir),
            "-DCMAKE_BUILD_TYPE=Release",
            "-DSKELCONV_BUILD_PYTHON=ON",
            "-DSKELCONV_BUILD_TESTS=OFF",
            "-DSKELCONV_BUILD_CODEGEN=OFF",
            "-DSKELCONV_BUILD_VERIFY=OFF",
            "-DSKELCONV_BUILD_BENCH=OFF",
            "-DSKELCONV_BUILD_FIGURES=OFF",
            "-DSKELCONV_INSTALL=OFF",
            f"-DSKELCONV_PYTHON={sys.executable}",
        ]
        if shutil.which("ccache"):
            configure.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        subprocess.run(configure, check=True)
        subprocess.run(["cmake", "--build", str(build_dir), "--target", ext.target, "--parallel", jobs], check=True)

        destination = Path(self.get_ext_fullpath(ext.name))
        destination.parent.mkdir(parents=True, exist_ok=True)
        module = next((build_dir / "python").glob("skelconv*.so"))
        shutil.copyfile(module, destination)
        grid_mesher = build_dir / "src" / "libskelconv_grid_mesher.so"
        shutil.copyfile(grid_mesher, destination.parent / grid_mesher.name)


setup(
    ext_modules=[CMakeExtension("skelconv", target="skelconv_python")],
    cmdclass={"build_ext": CMakeBuild},
)
