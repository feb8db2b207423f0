#!/usr/bin/env bash
# Benchmark of the neural histogram ([Shah24] Sec. 4.2; `microbake histogram --method neural`): per map, the bake
# (training) time, the asset's bytes against the exact table's, and the mean KL to the exact histogram per footprint
# side (8 to 256 texels) of the neural histogram, of a MIP pyramid of histograms of equal bytes ([DLW*22], the
# non-neural baseline) and of the whole map's histogram. Bakes with `microbake histogram` (timed by /usr/bin/time)
# and measures with the bench target tests/bench/neural_histogram_bench.cpp; prints Markdown.
#
#   bash scripts/bench-neural-histogram.sh [BUILD_DIR [ITERATIONS [MAP...]]]
#     default build/, the command's default iterations, and ../shared/data/real's leather_grain.png,
#     brushed_streaks_diagonal.png, metallic_flakes.png (512^2) and brick_floor.png (1024^2), read -Y with
#     --repair-invalid (../shared/data/real/SOURCES.md; metallic_flakes' convention is undetermined: auto).
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
iterations="${2:-}"
shift 2 2>/dev/null || shift $#
real=../shared/data/real
maps=("$@")
[ ${#maps[@]} -gt 0 ] || maps=("$real/leather_grain.png" "$real/brushed_streaks_diagonal.png"
                                "$real/metallic_flakes.png" "$real/brick_floor.png")
[ -f "$build/build.ninja" ] || { echo "bench: $build is not a configured build (scripts/build.sh $build)" >&2; exit 2; }
ninja -C "$build" microbake bench_neural_histogram >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "Machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //'); load average" \
  "$(cut -d' ' -f1 /proc/loadavg) at the start."
for map in "${maps[@]}"; do
  convention=-Y
  [ "$(basename "$map")" = metallic_flakes.png ] && convention=auto
  out="$work/$(basename "$map" .png).mbk"
  echo
  echo "### $(basename "$map") (--convention $convention --repair-invalid${iterations:+ --iterations $iterations})"
  echo
  /usr/bin/time -f "bake wall %e s, max RSS %M KB" "$build/microbake" histogram "$map" --convention "$convention" \
    --repair-invalid ${iterations:+--iterations "$iterations"} -q -o "$out" 2>&1 | grep -v '^microbake: warning'
  "$build/tests/bench_neural_histogram" "$out" "$map" "$convention" repair
done
