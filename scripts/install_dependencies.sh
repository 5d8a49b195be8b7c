#!/usr/bin/env bash
# Installs the Debian packages skelconv builds with, if any is missing;
# with --checks, also those only the check suite (scripts/checks.sh) uses:
# clang for the libFuzzer harnesses, Chromium for the viewer's browser
# test, CGAL's sample meshes for the reconstruction table.
# Needs root (or sudo) only when something has to be installed.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libginac-dev            # codegen/ only
  libeigen3-dev libboost-dev libboost-math-dev
  nlohmann-json3-dev libcli11-dev libfmt-dev
  libgtest-dev libbenchmark-dev libcgal-dev
  ccache                  # compiler cache: a rebuild after a branch switch or a regeneration costs what changed (CMakeLists.txt uses it when present)
  valgrind                # bench/: instruction counts
  libflint-arb-dev        # verify/: Arb ball arithmetic and acb_calc_integrate, the certified references (verify_certified_references)
  libgsl-dev              # bench/ only: GSL's adaptive QAG (61-point rule), the quadrature baseline
  python3-matplotlib python3-numpy  # papers_figures/: 2-D figures (Agg backend) and their claim checks; verify/heatmap.py
  python3-yaml            # verify/check_cluster_files.py: parses the GitHub Actions sweep workflow (ctest verify_cluster_files)
  libpng-dev              # skelconv skeletonize --report-image: the picture is written as PNG
  povray                  # papers_figures/render3d: headless shaded renders of meshes
  libopenvdb-dev libboost-iostreams-dev  # skelconv mesh --method grid (OpenVDB volumeToMesh; its CMake module needs Boost.Iostreams)
  glslang-tools           # tests/glsl: glslangValidator compiles generated/glsl as GLSL ES 3.00 (WebGL2) and 4.50 (ctest glsl_compiles)
  pybind11-dev python3-pybind11 python3-dev  # python/: the `import skelconv` module (pybind11 headers and CMake config, Python.h); its tests need python3-numpy
  python3-setuptools python3-wheel python3-venv  # `pip install --no-build-isolation .` (pyproject.toml, setup.py: the build backend) into a venv (docs/python.md)
)
# Only the check suite (scripts/checks.sh, --checks) runs these; CI and the main job do not install them.
if [ "${1:-}" = "--checks" ]; then
  packages+=(
    clang-14 libclang-rt-14-dev  # scripts/fuzz.sh: libFuzzer harnesses of the PLY/OBJ reader and the point lines (clang's -fsanitize=fuzzer)
    chromium                     # tests/view/check_view_browser.py (ctest label long): the `skelconv view` page rendered headless (WebGL2 on SwiftShader)
    libcgal-demo                 # tests/reconstruct/real_shapes.py (ctest label long): CGAL's sample meshes (hand, homer, dino, …), the real shapes of docs/reconstruction_medial.md
  )
fi

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
