#!/usr/bin/env bash
# The crease example (issue 5, [Parilov05]): a close-up of the corner where four panels of `gen panels` meet,
# about 25 screen pixels per texel. Generates the map and its exact crease lines (`gen --creases`), bakes ONLY the
# scene's crease asset, renders it with the reconstruction (the evaluator, 4 samples per pixel), with --reference
# (the exact side-aware normals from the raw map and curves, 4 x 4 rays per pixel) and with plain normal mapping
# (the same scene without the effect, examples/scenes/crease_plain.json: bilinear, MIP-mapped normals), compares
# both with the reference next to the reference's own noise floor (a second reference with another seed) and prints
# the render times. Writes EXR (linear) and PNG (for viewing) of each, rendered
# once per format.
#
#   examples/run_crease.sh [MICROBAKE [OUT_DIR]]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
exe="${1:-${MICROBAKE:-$here/../build/microbake}}"
out="${2:-${OUT_DIR:-$here/../out/crease}}"
scene="$here/scenes/crease.json"
plain="$here/scenes/crease_plain.json"
maps="$here/generated"
[[ -x "$exe" ]] || { echo "run_crease.sh: no microbake binary at '$exe'" >&2; exit 2; }
mkdir -p "$maps" "$out"
out="$(cd "$out" && pwd)"

"$exe" gen panels --size 256 --seed 1 -q -o "$maps/panels256.png" --creases "$maps/panels256.creases.json"
"$exe" bake "$scene" --out-dir "$out/assets"
# EXR to compare (linear), PNG to look at (examples/results/crease/scene_*.png are these PNGs).
for ext in exr png; do
  "$exe" render "$scene" --assets "$out/assets" --spp 4 -o "$out/scene_crease.$ext"
  "$exe" render "$scene" --reference 4 -o "$out/scene_reference.$ext"
  "$exe" render "$plain" --spp 4 -o "$out/scene_plain.$ext"
done
# The reference's own noise floor: a second reference with another jitter seed against the first.
"$exe" render "$scene" --reference 4 --seed 1 -o "$out/scene_reference_seed1.exr"
for name in scene_reference_seed1 scene_crease scene_plain; do
  echo "== $name against the reference"
  "$exe" compare "$out/$name.exr" "$out/scene_reference.exr"
done
