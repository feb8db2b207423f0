#!/usr/bin/env bash
# Benchmark of `microbake colormap` (asset kind colormap): what the table size costs. For the example colour maps
# (a smooth-ish terrain map with one hard edge, and hard-edged stripes) at table sizes 16x16 .. 1024x1024: the
# lookup error (max and RMS of |bilinear lookup - exact convolution| over every cell centre, linear RGB), the naive
# error the table removes (max |C(m) - filtered|), bake time (median of 3, from the command's summary line) and file
# size. Prints a Markdown table on stdout.
#
#   bash scripts/bench-colormap.sh [BUILD_DIR]        # default build/ (a Release build)
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
exe="$build/microbake"
[ -x "$exe" ] || { echo "bench: $exe not found (build first: scripts/build.sh $build)" >&2; exit 2; }
command -v jq >/dev/null || { echo "bench: jq is needed (apt-get install jq)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
runs=3
median() { sort -g | sed -n "$(((runs + 1) / 2))p"; }

echo "| map | table | file | bake (ms) | lookup max error | lookup RMS error | naive max error |"
echo "|---|---|---|---|---|---|---|"
for map in terrain stripes; do
  for size in 16x16 32x32 64x64 128x128 256x256 512x512 1024x1024; do
    lines=""
    for _ in $(seq $runs); do
      lines+=$("$exe" colormap "examples/colormaps/$map.json" --size "$size" -o "$work/out.mbk")$'\n'
    done
    bake=$(sed -n 's/.*, bake \([0-9.e-]*\) s,.*/\1/p' <<<"$lines" | median)
    stats=$("$exe" info "$work/out.mbk" --format json | jq -c '.metadata.statistics')
    printf '| %s | %s | %s KB | %.1f | %.2e | %.2e | %.3f |\n' "$map" "$size" \
      "$(( ($(stat -c %s "$work/out.mbk") + 512) / 1024 ))" "$(echo "$bake * 1000" | bc -l)" \
      "$(jq '.lookup_max_error' <<<"$stats")" "$(jq '.lookup_rms_error' <<<"$stats")" \
      "$(jq '.naive_max_error' <<<"$stats")"
  done
done
