#!/usr/bin/env bash
# The glints example (issue 3): an infinite, non-repeating microstructure blended from two small example maps
# (scratches with histogram-preserving blending on a plane, flakes with `none` on a bent quad) under two point
# lights and a sky. Generates the examples, bakes ONLY their lut and rmq assets, renders the scene with the
# glint P-NDF (the evaluator, 1 sample per pixel, 16 in the pixels a silhouette crosses: --edge-spp), with --reference (brute force over the infinite
# microstructure: the exact point NDF of 16 x 16 rays per pixel) and with plain normal mapping (the same scene
# without its effects), a second reference with another jitter seed (the reference's own noise floor), compares
# each with the reference (per pixel, and the relative L1 of 8 x 8 pixel block means: `compare --block 8`) and
# prints the times. The effect is within the goal where its block L1 is at most twice the floor's. Then the same
# per shape and per light, at half the resolution: the scene with one shape (plane, quad) or one point light
# (light0, light1, no sky) at a time, each with its own floor, one line each.
# SCENE is any scene of the same layout (two shapes, two point lights): examples/scenes/glints_real.json puts real
# maps made by other people (../shared/data/real beside the repository, never committed) in place of the generated
# ones.
#
#   examples/run_glints.sh [MICROBAKE [OUT_DIR [SCENE]]]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
exe="${1:-${MICROBAKE:-$here/../build/microbake}}"
out="${2:-${OUT_DIR:-$here/../out/glints}}"
scene_in="${3:-$here/scenes/glints.json}"
maps="$here/generated"
[[ -x "$exe" ]] || { echo "run_glints.sh: no microbake binary at '$exe'" >&2; exit 2; }
[[ -f "$scene_in" ]] || { echo "run_glints.sh: no scene at '$scene_in'" >&2; exit 2; }
mkdir -p "$maps" "$out"
out="$(cd "$out" && pwd)"
# The scene with its maps' paths made absolute (its variants below live in other folders), and without effects.
scene="$out/scene.json"
plain="$out/scene_plain.json"
jq --arg dir "$(cd "$(dirname "$scene_in")" && pwd)" \
  '(.materials[] | select(.normal_map) | .normal_map.path) |= (if startswith("/") then . else $dir + "/" + . end)' \
  "$scene_in" >"$scene"
jq 'del(.materials[].effects)' "$scene" >"$plain"

"$exe" gen scratches --size 512 --seed 1 -q -o "$maps/scratches512.png"
"$exe" gen flakes --size 512 --seed 1 -q -o "$maps/flakes512.png"
"$exe" bake "$scene" --out-dir "$out/assets"
"$exe" bake "$plain" --out-dir "$out/plain_assets"
"$exe" render "$scene" --assets "$out/assets" --edge-spp 16 -o "$out/glints.exr"
"$exe" render "$scene" --reference 16 -o "$out/glints_reference.exr"
"$exe" render "$scene" --reference 16 --seed 1 -o "$out/glints_reference_seed1.exr"
"$exe" render "$plain" --assets "$out/plain_assets" -o "$out/glints_plain.exr"
for name in glints glints_reference glints_plain; do
  oiiotool "$out/$name.exr" --colorconvert linear sRGB -o "$out/$name.png"
  echo "$name: $(iinfo --stats "$out/$name.exr" | grep 'Stats Avg' | sed 's/ *Stats Avg: //')"
done
for name in glints_reference_seed1 glints glints_plain; do
  echo "== $name against the reference"
  "$exe" compare "$out/$name.exr" "$out/glints_reference.exr" --block 8
done

# Per shape and per light (half resolution): effect and floor on 8 x 8 blocks of the same reference.
echo "== per shape and per light (half resolution; block L1 of 8 x 8 means, effect / floor of two references)"
block_l1() { "$exe" compare "$1" "$2" --block 8 --format json | jq -r '.block_relative_l1'; }
for variant in plane quad light0 light1; do
  case "$variant" in
    plane) pick='.shapes |= [.[0]]' ;;
    quad) pick='.shapes |= [.[1]]' ;;
    light0) pick='.lights |= [.[0]]' ;;
    light1) pick='.lights |= [.[1]]' ;;
  esac
  dir="$out/$variant"
  mkdir -p "$dir"
  jq "$pick | .camera.width /= 2 | .camera.height /= 2" "$scene" >"$dir/scene.json"
  "$exe" bake "$dir/scene.json" --out-dir "$dir/assets" -q
  "$exe" render "$dir/scene.json" --assets "$dir/assets" --edge-spp 16 -q -o "$dir/effect.exr"
  "$exe" render "$dir/scene.json" --reference 16 -q -o "$dir/reference.exr"
  "$exe" render "$dir/scene.json" --reference 16 --seed 1 -q -o "$dir/reference_seed1.exr"
  effect=$(block_l1 "$dir/effect.exr" "$dir/reference.exr")
  floor=$(block_l1 "$dir/reference_seed1.exr" "$dir/reference.exr")
  echo "$variant: effect $effect, floor $floor, ratio $(echo "scale=2; $effect / $floor" | bc)"
done
