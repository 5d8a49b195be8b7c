#!/usr/bin/env bash
# Compiles every function of generated/glsl/*.glsl (segment, point and
# SCALIS kernels) with glslangValidator
# (Debian glslang-tools, the Khronos reference front end) as GLSL ES 3.00
# (WebGL2) and desktop GLSL 4.50: each file is wrapped in a minimal fragment
# shader whose main() calls every function it defines, so every one is
# parsed, type-checked and reachable.
#
#   check_glsl_compiles.sh GLSL_FOLDER [--inject-fault]
#
# --inject-fault checks copies of the files, each with one more kernel
# function, which calls an undeclared function: the check must then fail on
# every file and print "CHECK-FAILED: shader does not compile: ..." with the
# validator's error (ctest glsl_compile_check_can_fail).
set -euo pipefail
folder=$1
fault=${2:-}
validator=$(command -v glslangValidator || true)
if [ -z "$validator" ]; then
  echo "check_glsl_compiles: glslangValidator not found (Debian package glslang-tools; scripts/install_dependencies.sh)" >&2
  exit 1
fi
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
shopt -s nullglob
files=("$folder"/*.glsl)
if [ ${#files[@]} -eq 0 ]; then
  echo "check_glsl_compiles: no .glsl file in $folder" >&2
  exit 1
fi
if [ "$fault" = "--inject-fault" ]; then
  mkdir "$scratch/faulty"
  for file in "${files[@]}"; do
    copy="$scratch/faulty/$(basename "$file")"
    input=$(sed -n 's/^struct \([A-Za-z]*Input\) {$/\1/p' "$file" | head -1)
    { cat "$file"; printf 'float injected_fault(%s x) {\n  return undeclared_kernel(0.0);\n}\n' "$input"; } > "$copy"
  done
  files=("$scratch/faulty"/*.glsl)
fi
status=0
for file in "${files[@]}"; do
  # Every kernel function: float NAME(INPUT x) or (…, out vec3 grad), INPUT
  # the file's input struct (SegmentInput, PointInput, ScalisSegmentInput).
  mapfile -t values < <(sed -n 's/^float \([a-z0-9_]*\)(\([A-Za-z]*Input\) [a-z]*) {$/\1(u_\2)/p' "$file")
  mapfile -t both < <(sed -n 's/^float \([a-z0-9_]*\)(\([A-Za-z]*Input\) [a-z]*, out vec3 grad) {$/\1(u_\2, grad)/p' "$file")
  mapfile -t inputs < <(sed -n 's/^struct \([A-Za-z]*Input\) {$/\1/p' "$file")
  if [ $((${#values[@]} + ${#both[@]})) -eq 0 ]; then
    echo "check_glsl_compiles: $file defines no kernel function" >&2
    status=1
    continue
  fi
  for version in "300 es" "450"; do
    shader="$scratch/$(basename "$file" .glsl)_${version// /_}.frag"
    {
      echo "#version $version"
      [ "$version" = "300 es" ] && echo "precision highp float;"
      cat "$file"
      for t in "${inputs[@]}"; do echo "uniform $t u_$t;"; done
      echo "out vec4 colour;"
      echo "void main() {"
      echo "  float sum = 0.0;"
      echo "  vec3 grad = vec3(0.0);"
      for f in "${values[@]}"; do echo "  sum += $f;"; done
      for f in "${both[@]}"; do echo "  sum += $f + grad.x + grad.y + grad.z;"; done
      echo "  colour = vec4(sum);"
      echo "}"
    } > "$shader"
    if "$validator" "$shader" > "$scratch/log" 2>&1; then
      echo "check_glsl_compiles: $(basename "$file") as GLSL $version: ${#values[@]} f and ${#both[@]} f+grad functions compile"
    else
      echo "CHECK-FAILED: shader does not compile: $(basename "$file") as GLSL $version: $(grep -m1 '^ERROR:' "$scratch/log")"
      echo "check_glsl_compiles: $(basename "$file") as GLSL $version does not compile:" >&2
      head -20 "$scratch/log" >&2
      status=1
    fi
  done
done
exit $status
