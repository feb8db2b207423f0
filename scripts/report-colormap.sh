#!/usr/bin/env bash
# The render half of examples/results/colormap/REPORT.md ([Heitz13] colour-mapped textures and surfaces): the
# example scene examples/scenes/colormap.json (a plane receding to the horizon with colour-mapped noise, a
# colormap-height sphere and a colormap-slope sphere) rendered naive (C of the filtered driver, the scene with
# every "mode" set to "naive"), filtered (the paper) and as `--reference N` (N x N rays per pixel, C of the raw
# driver and numerically integrated microsurfaces). Writes the three PNGs to examples/results/colormap/ and prints
# a Markdown table: per case (the scene with only that shape; background included in the RMSE), the error of naive and filtered against the reference (`microbake compare`) and the render times (from
# `render`'s summary line; one run each, on a shared machine).
#
#   bash scripts/report-colormap.sh [BUILD_DIR] [N]     # default build/ (a Release build), N = 8
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
n="${2:-8}"
exe="$build/microbake"
[ -x "$exe" ] || { echo "report: $exe not found (build first: scripts/build.sh $build)" >&2; exit 2; }
command -v jq >/dev/null || { echo "report: jq is needed (apt-get install jq)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
out=examples/results/colormap
scene=examples/scenes/colormap.json
maps="$(pwd)/examples/colormaps/"

# The scene with paths made absolute, in mode $1, keeping the shapes whose indices are in $2 (a jq array).
variant() {
  jq --arg mode "$1" --argjson keep "$2" --arg maps "$maps" '
    .shapes |= [to_entries[] | select(.key as $k | $keep | index($k)) | .value]
    | (.shapes | map(.material)) as $used
    | .materials |= with_entries(select(.key as $m | $used | index($m)))
    | .materials[].effects[] |= (.mode = $mode | .colormap |= sub("^\\.\\./colormaps/"; $maps))' "$scene"
}
seconds() { sed -n 's/.*, \([0-9.]*\) s$/\1/p'; }
rmse() { "$exe" compare "$1" "$2" --format json | jq '.rmse'; }

echo "| case | naive RMSE | filtered RMSE | naive render (s) | filtered render (s) | reference ${n}x${n} render (s) |"
echo "|---|---|---|---|---|---|"
for entry in 'noise plane (colormap):[0]' 'height sphere (colormap-height):[1]' 'slope sphere (colormap-slope):[2]'; do
  name="${entry%%:*}"
  keep="${entry##*:}"
  for mode in naive filtered; do
    variant "$mode" "$keep" >"$work/$mode.json"
    "$exe" bake "$work/$mode.json" -q
  done
  t_naive=$("$exe" render "$work/naive.json" -o "$work/naive.exr" | seconds)
  t_filtered=$("$exe" render "$work/filtered.json" -o "$work/filtered.exr" | seconds)
  t_ref=$("$exe" render "$work/filtered.json" --reference "$n" -o "$work/reference.exr" | seconds)
  printf '| %s | %.4f | %.4f | %s | %s | %s |\n' "$name" "$(rmse "$work/naive.exr" "$work/reference.exr")" \
    "$(rmse "$work/filtered.exr" "$work/reference.exr")" "$t_naive" "$t_filtered" "$t_ref"
done
# The pictures: the whole scene.
for mode in naive filtered; do
  variant "$mode" '[0,1,2]' >"$work/$mode.json"
  "$exe" bake "$work/$mode.json" -q
  "$exe" render "$work/$mode.json" -o "$out/$mode.png" -q
done
"$exe" render "$work/filtered.json" --reference "$n" -o "$out/reference.png" -q
