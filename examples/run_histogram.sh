#!/usr/bin/env bash
# The histogram example ([Shah24]): glints under an environment map and a point light, with a roughness texture
# that varies across the surface. Generates the maps (scratches on a plane, brushed on a bent quad), the studio
# environment and the roughness texture (examples/lighting/make_lighting.py), bakes ONLY the maps' histogram assets
# (plus the baselines), renders the scene with the effect (binned P-NDFs, 1 sample per pixel), with --reference
# (Eq. 2 by Monte Carlo: RAYS x RAYS rays per pixel, each the exact texel normal, 4 lobe directions per ray for the
# environment) and with plain normal mapping (the same scene without its effects), a second reference with another
# jitter seed (the reference's own noise floor), compares each with the reference (per pixel, and the relative L1
# of 8 x 8 pixel block means) and prints the times. Then the same per light at half resolution (the environment
# alone, the point light alone), each with its own floor, one line each. Pictures: PNG (sRGB) beside each EXR, and
# strip.png (effect | reference | plain, left to right).
# SCENE is any scene of the same layout: examples/scenes/histogram_real.json puts a real map made by other people
# (../shared/data/real beside the repository, never committed) on the plane.
#
#   examples/run_histogram.sh [MICROBAKE [OUT_DIR [SCENE [RAYS]]]]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
exe="${1:-${MICROBAKE:-$here/../build/microbake}}"
out="${2:-${OUT_DIR:-$here/../out/histogram}}"
scene_in="${3:-$here/scenes/histogram.json}"
rays="${4:-16}"
maps="$here/generated"
[[ -x "$exe" ]] || { echo "run_histogram.sh: no microbake binary at '$exe'" >&2; exit 2; }
[[ -f "$scene_in" ]] || { echo "run_histogram.sh: no scene at '$scene_in'" >&2; exit 2; }
mkdir -p "$maps" "$out"
out="$(cd "$out" && pwd)"
# The scene with its paths made absolute (its variants live in other folders), and without effects.
scene="$out/scene.json"
plain="$out/scene_plain.json"
dir="$(cd "$(dirname "$scene_in")" && pwd)"
jq --arg dir "$dir" 'def abs: if startswith("/") then . else $dir + "/" + . end;
  (.materials[] | select(.normal_map) | .normal_map.path) |= abs
  | (.materials[].effects[]? | select(type == "object" and has("roughness_map")) | .roughness_map) |= abs
  | (.lights[] | select(.type == "environment") | .path) |= abs' "$scene_in" >"$scene"
jq 'del(.materials[].effects)' "$scene" >"$plain"

"$exe" gen scratches --size 256 --seed 1 -q -o "$maps/scratches256.png"
"$exe" gen brushed --size 256 --seed 1 -q -o "$maps/brushed256.png"
python3 "$here/lighting/make_lighting.py" "$maps"
"$exe" bake "$scene" --out-dir "$out/assets"
"$exe" bake "$plain" --out-dir "$out/plain_assets"
"$exe" render "$scene" --assets "$out/assets" -o "$out/histogram.exr"
"$exe" render "$scene" --reference "$rays" -o "$out/histogram_reference.exr"
"$exe" render "$scene" --reference "$rays" --seed 1 -o "$out/histogram_reference_seed1.exr"
"$exe" render "$plain" --assets "$out/plain_assets" -o "$out/histogram_plain.exr"
for name in histogram histogram_reference histogram_plain; do
  oiiotool "$out/$name.exr" --colorconvert linear sRGB -o "$out/$name.png"
  echo "$name: $(iinfo --stats "$out/$name.exr" | grep 'Stats Avg' | sed 's/ *Stats Avg: //')"
done
oiiotool "$out/histogram.png" "$out/histogram_reference.png" "$out/histogram_plain.png" --mosaic 3x1 -o "$out/strip.png"
for name in histogram_reference_seed1 histogram histogram_plain; do
  echo "== $name against the reference"
  "$exe" compare "$out/$name.exr" "$out/histogram_reference.exr" --block 8
done

echo "== per light (half resolution; block L1 of 8 x 8 means, effect / floor of two references)"
block_l1() { "$exe" compare "$1" "$2" --block 8 --format json | jq -r '.block_relative_l1'; }
for variant in environment point; do
  case "$variant" in
    environment) pick='.lights |= map(select(.type == "environment"))' ;;
    point) pick='.lights |= map(select(.type == "point"))' ;;
  esac
  sub="$out/$variant"
  mkdir -p "$sub"
  jq "$pick | .camera.width /= 2 | .camera.height /= 2" "$scene" >"$sub/scene.json"
  "$exe" bake "$sub/scene.json" --out-dir "$out/assets" -q
  "$exe" render "$sub/scene.json" --assets "$out/assets" -q -o "$sub/effect.exr"
  "$exe" render "$sub/scene.json" --reference "$rays" -q -o "$sub/reference.exr"
  "$exe" render "$sub/scene.json" --reference "$rays" --seed 1 -q -o "$sub/reference_seed1.exr"
  effect=$(block_l1 "$sub/effect.exr" "$sub/reference.exr")
  floor=$(block_l1 "$sub/reference_seed1.exr" "$sub/reference.exr")
  echo "$variant: effect $effect, floor $floor, ratio $(echo "scale=2; $effect / $floor" | bc)"
done
