#!/usr/bin/env bash
# The glints scene's far field at full pixel size (issue 11): the plane of examples/scenes/glints.json seen through
# a 200 x 58 window aimed at the upper-left crop of the 384 x 216 view (pixels 0-200 x 62-120; same camera
# position, the field of view narrowed to keep the pixel size), where single sparkles are smaller than a pixel.
# Renders the effect (1 sample per pixel), two references of 16 x 16 rays and two of 64 x 64 rays per pixel
# (jitter seeds 0 and 1), then prints the sparkle statistics of each (scripts/sparkle-statistics.py: pixels above
# twice their row's median, their summed excess and its quantiles) and the relative L1 of each against the first
# 64 x 64-ray reference on 8 x 8, 2 x 2 and 1 x 1 blocks. Run examples/run_glints.sh first (it generates the map).
#
#   examples/run_glints_farfield.sh [MICROBAKE [OUT_DIR]]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
exe="${1:-${MICROBAKE:-$here/../build/microbake}}"
out="${2:-${OUT_DIR:-$here/../out/glints_farfield}}"
scene="$here/scenes/glints_farfield.json"
[[ -x "$exe" ]] || { echo "run_glints_farfield.sh: no microbake binary at '$exe'" >&2; exit 2; }
[[ -f "$here/generated/scratches512.png" ]] || { echo "run_glints_farfield.sh: run examples/run_glints.sh first" >&2; exit 2; }
mkdir -p "$out"
"$exe" bake "$scene" --out-dir "$out/assets" -q
"$exe" render "$scene" --assets "$out/assets" -o "$out/effect.exr"
for rays in 16 64; do
  for seed in 0 1; do "$exe" render "$scene" --reference "$rays" --seed "$seed" -o "$out/reference${rays}_seed$seed.exr"; done
done
images=("$out/effect.exr" "$out"/reference16_seed{0,1}.exr "$out"/reference64_seed{0,1}.exr)
python3 "$here/../scripts/sparkle-statistics.py" --crop 0,4,200,58 "${images[@]}"
echo "relative L1 against reference64_seed0.exr on 8 x 8 / 2 x 2 / 1 x 1 blocks"
for image in "${images[@]}"; do
  [[ "$image" == "$out/reference64_seed0.exr" ]] && continue
  line="$(basename "$image"):"
  for block in 8 2 1; do
    line+=" $("$exe" compare "$image" "$out/reference64_seed0.exr" --block "$block" --format json | jq -r '.block_relative_l1')"
  done
  echo "$line"
done
