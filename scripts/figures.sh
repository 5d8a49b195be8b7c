#!/usr/bin/env bash
# Regenerates the papers' figures and tables (papers_figures/, docs/figures.md):
# installs what is missing, builds the skelconv command, draws every registered
# figure into a results folder, checks each claim and writes
# papers_figures/GALLERY.md with the PNGs in papers_figures/images/ and one
# record per figure in papers_figures/results/.
#
#   scripts/figures.sh                          everything (full resolution) + gallery
#   scripts/figures.sh --only NAME...           some figures, into the results folder only
#   scripts/figures.sh --only NAME... --gallery some figures, their images and records
#                                               refreshed, the gallery rewritten
#   scripts/figures.sh --gallery-only           the gallery rewritten from the committed
#                                               records and images (seconds, nothing drawn)
#   scripts/figures.sh --out DIR                results folder (default build/figures)
set -euo pipefail
cd "$(dirname "$0")/.."
out=build/figures
only=()
gallery=no
while [ $# -gt 0 ]; do
  case "$1" in
    --out) out="$2"; shift 2 ;;
    --only) shift; while [ $# -gt 0 ] && [ "${1#--}" = "$1" ]; do only+=("$1"); shift; done ;;
    --gallery) gallery=yes; shift ;;
    --gallery-only) gallery=only; shift ;;
    *) echo "figures.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
# Debian's python3 (python3-matplotlib), not whatever python3 comes first on PATH.
python=/usr/bin/python3
if [ "$gallery" = only ]; then
  exec "$python" papers_figures/run.py --gallery-only papers_figures/GALLERY.md
fi
scripts/install_dependencies.sh
echo "figures.sh: building skelconv and the renderer's test mesh"
scripts/build.sh --target skelconv skelconv_figures_uv_sphere > /dev/null
args=(--skelconv build/release/src/skelconv --out "$out" --check)
if [ ${#only[@]} -gt 0 ]; then
  args+=(--only "${only[@]}")
  if [ "$gallery" = yes ]; then args+=(--gallery papers_figures/GALLERY.md); fi
else
  args+=(--gallery papers_figures/GALLERY.md)
fi
"$python" papers_figures/run.py "${args[@]}"
if [ ${#only[@]} -eq 0 ]; then
  # The 3-D renderer on its test mesh (a UV sphere written by skelconv::write_mesh):
  # the 3-D figures themselves mesh their skeletons with `skelconv mesh`.
  echo "figures.sh: the renderer's test mesh"
  mkdir -p "$out"
  build/release/papers_figures/skelconv_figures_uv_sphere "$out/uv_sphere.ply"
  "$python" papers_figures/render3d/render_mesh.py "$out/uv_sphere.ply" papers_figures/images/render3d_uv_sphere.png
fi
