#!/usr/bin/env bash
# Start-up time of the commands that read no image (issue: every command paid for loading OpenImageIO's ~260 shared
# libraries; they now live in the module libmicrobake_image_io.so, loaded on the first image read or write).
# Runs /bin/true and each command RUNS times (default 20), interleaved, on a small asset and the demo scene, and
# prints per start the wall and CPU milliseconds and the ratio to /bin/true, and the dynamic linker's relocation
# count. Usage: scripts/bench-startup.sh [BUILD_DIR [BASELINE_MICROBAKE]]; a baseline binary (e.g. one built from an
# older commit) is measured in the same run for a same-run ratio.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
exe="$(realpath "$build/microbake")"
base="${2:+$(realpath "$2")}"
runs="${RUNS:-20}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Inputs: a 64 x 64 mip asset, the demo scene with its maps, two small PNGs for compare.
"$exe" gen bumps --size 64 -q -o "$work/b.png"
"$exe" gen bumps --size 64 --seed 2 -q -o "$work/c.png"
"$exe" mip "$work/b.png" -q -o "$work/b.mbk"
mkdir -p "$work/examples/scenes" "$work/examples/generated"
cp examples/scenes/demo.json "$work/examples/scenes/"
for kind in $(grep -o 'generated/[a-z_]*\.png' examples/scenes/demo.json | sed 's|generated/\(.*\)\.png|\1|' | sort -u); do
  "$exe" gen "$kind" --size 64 --seed 1 -q -o "$work/examples/generated/$kind.png"
done

commands=("--version" "info b.mbk" "validate b.mbk" "plan examples/scenes/demo.json -o plan.ninja --out-dir assets"
          "compare b.png c.png")
# Every command must succeed (a failing one would look fast).
for e in $exe ${base:+$base}; do
  for c in "${commands[@]}"; do
    (cd "$work" && $e $c >/dev/null 2>&1) || { echo "bench-startup: '$e $c' failed" >&2; exit 1; }
  done
done
# One timed loop of RUNS starts of "$@" in $work: prints "wall_ms cpu_ms" per start.
per_start() {
  local t0 t1 c
  t0=$(date +%s%N)
  c=$( { /usr/bin/time -f '%U %S' bash -c "cd '$work' && for i in \$(seq $runs); do $* >/dev/null 2>&1; done" ; } 2>&1 | tail -1)
  t1=$(date +%s%N)
  awk -v w="$(( (t1 - t0) / 1000 ))" -v c="$c" -v n="$runs" 'BEGIN { split(c, a, " "); printf "%.1f %.1f\n", w / 1000 / n, (a[1] + a[2]) * 1000 / n }'
}
true_ms=$(per_start /bin/true)
printf '| command | wall ms per start | CPU ms per start | wall / /bin/true | relocations at start-up |\n|---|---|---|---|---|\n'
printf '| /bin/true | %s | %s | 1 | |\n' ${true_ms}
for exe_name in ${base:+base} now; do
  e=$exe; [ "$exe_name" = base ] && e=$base
  for c in "${commands[@]}"; do
    read -r wall cpu < <(per_start "$e" "$c")
    relocs=$(cd "$work" && LD_DEBUG=statistics $e $c 2>&1 >/dev/null | sed -n 's/.*number of relocations: *\([0-9]*\).*/\1/p' | head -1)
    printf '| %s%s | %s | %s | %s | %s |\n' "${base:+$exe_name: }" "microbake $c" "$wall" "$cpu" \
      "$(awk -v a="$wall" -v b="${true_ms%% *}" 'BEGIN { printf "%.1f", a / (b > 0 ? b : 1) }')" "${relocs:-?}"
  done
done
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
