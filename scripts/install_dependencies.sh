#!/usr/bin/env bash
# Installs the Debian packages skelconv builds with, if any is missing.
# Needs root (or sudo) only when something has to be installed.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libginac-dev            # codegen/ only
  libeigen3-dev libboost-dev libboost-math-dev
  nlohmann-json3-dev libcli11-dev libfmt-dev
  libgtest-dev libbenchmark-dev libcgal-dev
  valgrind                # bench/: instruction counts
  python3-matplotlib python3-numpy  # papers_figures/: 2-D figures (Agg backend) and their claim checks
  povray                  # papers_figures/render3d: headless shaded renders of meshes
  libopenvdb-dev libboost-iostreams-dev  # skelconv mesh --method grid (OpenVDB volumeToMesh; its CMake module needs Boost.Iostreams)
  pybind11-dev python3-pybind11 python3-dev  # python/: the `import skelconv` module (pybind11 headers and CMake config, Python.h); its tests need python3-numpy
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install_dependencies: all packages present"
  exit 0
fi
echo "install_dependencies: installing ${missing[*]}"
sudo_cmd=""
[ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo_cmd apt-get update -qq
$sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
