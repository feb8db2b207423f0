#!/usr/bin/env bash
# The built-in example: generates the demo scene's normal maps, bakes the assets its effects need, renders
# it with the reference shader evaluator and with the brute-force reference, compares the two, and renders
# brute force at 2 x 2 rays per pixel as the yardstick the filtered render has to beat.
#
#   examples/run_example.sh [MICROBAKE [OUT_DIR]]
#
# MICROBAKE is the built binary (default: $MICROBAKE, else build/microbake beside this folder); OUT_DIR
# receives the assets and images (default: $OUT_DIR, else out/example). The maps are written to
# examples/generated/, where examples/scenes/demo.json expects them. Takes a few seconds on 2 cores.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
exe="${1:-${MICROBAKE:-$here/../build/microbake}}"
out="${2:-${OUT_DIR:-$here/../out/example}}"
scene="$here/scenes/demo.json"
maps="$here/generated"

if [[ ! -x "$exe" ]]; then
  echo "run_example.sh: no microbake binary at '$exe' (pass it as the first argument or set MICROBAKE)" >&2
  exit 2
fi
mkdir -p "$maps" "$out"
out="$(cd "$out" && pwd)"

echo "== generating normal maps into $maps"
for kind in bumps leather panels; do
  "$exe" gen "$kind" --size 256 --seed 1 -o "$maps/$kind.png"
done

echo "== baking the assets the scene's effects need"
"$exe" bake "$scene" --out-dir "$out/assets"

echo "== rendering (effects, 4 samples per pixel)"
"$exe" render "$scene" --assets "$out/assets" --spp 4 -o "$out/demo.exr"
"$exe" render "$scene" --assets "$out/assets" --spp 4 -o "$out/demo.png"

echo "== rendering the brute-force reference (6 x 6 rays per pixel, unfiltered normals)"
"$exe" render "$scene" --reference 6 -o "$out/demo_reference.exr"
"$exe" render "$scene" --reference 6 -o "$out/demo_reference.png"

echo "== comparing the render with the reference"
"$exe" compare "$out/demo.exr" "$out/demo_reference.exr"
"$exe" compare "$out/demo.exr" "$out/demo_reference.exr" --format json > "$out/compare.json"

echo "== the yardstick: brute force at 2 x 2 rays per pixel (same sample count), against the same reference"
"$exe" render "$scene" --reference 2 --seed 1 -o "$out/demo_brute_force_2x2.exr"
"$exe" compare "$out/demo_brute_force_2x2.exr" "$out/demo_reference.exr" | grep -E '^(rmse|block_l1)'

echo
echo "outputs in $out:"
echo "  assets/              baked assets (.mbk; inspect with '$exe info FILE')"
echo "  demo.png, demo.exr   the render (PNG tone-mapped for viewing, EXR linear)"
echo "  demo_reference.*     the brute-force reference"
echo "  compare.json         error metrics of the render against the reference"
echo "  demo_brute_force_2x2.exr  brute force at 2 x 2 rays: compare its time and RMSE with the render's"
