#!/usr/bin/env bash
# The speed benchmark of the bakers (issue 16): every bake against its yardstick in one run on this machine, with
# --threads 1 and 2, medians of interleaved runs (each run goes once through every bake and yardstick, so load
# from other work on the shared machine spreads over all of them), peak RSS of each process (GNU time), and the
# goal and pass/fail per row. Yardsticks: memcpy of as many bytes as the bake's output file (tests/bench/
# memcpy_bench.cpp, fresh destination pages) for every bake, and OpenImageIO's maketx (same f32 payload, box
# filter, no compression, same thread count) for mip.
#
# Writes examples/results/BENCH.md; with --quick, smaller maps (the absolute goals are then not judged) and the
# table goes to stdout only, for iterating.
#
#   bash scripts/bench.sh [--quick] [BUILD_DIR]         # default build/ (Release)
#   BENCH_RUNS=N (>= 3, default 3) runs; BENCH_VMF_SIZE=N runs the vmf row on an N x N map instead;
#   BENCH_ROWS="vmf sh ..." runs only those rows and prints the table (BENCH.md keeps every row)
set -euo pipefail
cd "$(dirname "$0")/.."
quick=0
if [ "${1:-}" = --quick ]; then quick=1; shift; fi
build="${1:-build}"
exe="$build/microbake"
[ -x "$exe" ] || { echo "bench: $exe not found (build first: scripts/build.sh $build)" >&2; exit 2; }
for tool in maketx jq bc /usr/bin/time; do
  command -v "$tool" >/dev/null || { echo "bench: $tool is needed (bash scripts/install-deps.sh)" >&2; exit 2; }
done
cmake --build "$build" --target bench_memcpy >/dev/null
memcpy="$build/tests/bench_memcpy"
runs="${BENCH_RUNS:-3}"
[ "$runs" -ge 3 ] || { echo "bench: BENCH_RUNS must be >= 3" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Map sizes: the issue's rows, or a quick set (about 1/16 of the texels).
if [ $quick = 1 ]; then
  vmf_n=256 sh_n=512 rmq_small=128 rmq_large=512 crease_n=256 crease_segments=2500 mip_n=512
else
  vmf_n=2048 sh_n=2048 rmq_small=512 rmq_large=2048 crease_n=1024 crease_segments=10000 mip_n=2048
fi
# The vmf row alone may be run smaller (BENCH_VMF_SIZE): at 2048^2 it is most of the benchmark's time.
vmf_n="${BENCH_VMF_SIZE:-$vmf_n}"
for n in $(printf '%s\n' 1 $vmf_n $sh_n $rmq_small $rmq_large $crease_n $mip_n | sort -un); do
  "$exe" gen bumps --size "$n" -q -o "$work/bumps$n.exr"
done
python3 scripts/random-curves.py "$work/curves.json" "$crease_n" "$crease_segments"

# Rows: name|map size|microbake arguments after the command's input (the input is bumps<size>.exr)|yardstick.
rows=(
  "vmf|$vmf_n|vmf --lobes 4|memcpy"
  "sh|$sh_n|sh --order 8|memcpy"
  "rmq|$rmq_small|rmq|memcpy+write"
  "rmq|$rmq_large|rmq|memcpy+write"
  "crease|$crease_n|crease --curves $work/curves.json|memcpy"
  "mip|$mip_n|mip|maketx"
)
if [ -n "${BENCH_ROWS:-}" ]; then
  selected=()
  for row in "${rows[@]}"; do
    for name in $BENCH_ROWS; do [ "${row%%|*}" = "$name" ] && selected+=("$row"); done
  done
  [ ${#selected[@]} -gt 0 ] || { echo "bench: BENCH_ROWS names no row (vmf sh rmq crease mip)" >&2; exit 2; }
  rows=("${selected[@]}")
fi

# Runs a command under GNU time; appends its wall seconds, its "bake S s" stage (the wall time when it prints
# none; with stages=bake+write, its bake and write stages together) and its peak RSS in KiB to
# $work/<key>.{wall,bake,rss}.
measure() {
  local key="$1" stages="$2"
  shift 2
  /usr/bin/time -f '%e %M' -o "$work/time" "$@" >"$work/stdout"
  local wall rss bake write
  read -r wall rss <"$work/time"
  bake=$(sed -n 's/.*[;,] bake \([0-9.e-]*\) s,.*/\1/p' "$work/stdout")
  write=$(sed -n 's/.*, write \([0-9.e-]*\) s$/\1/p' "$work/stdout")
  [ "$stages" = bake+write ] && [ -n "$bake" ] && bake=$(calc "$bake + $write")
  echo "$wall" >>"$work/$key.wall"
  echo "${bake:-$wall}" >>"$work/$key.bake"
  echo "$rss" >>"$work/$key.rss"
}
median() { sort -g "$1" | sed -n "$(((runs + 1) / 2))p"; }
calc() { echo "scale=6; $1" | bc -l; }
fmt() { printf "%.${2:-2}f" "$1"; }
le() { [ "$(echo "$1 <= $2" | bc -l)" = 1 ]; }
verdict() { if le "$1" "$2"; then echo "pass"; else echo "**FAIL**"; fi; }

for run in $(seq "$runs"); do
  echo "bench: run $run of $runs" >&2
  # The process's floor: a bake with nothing to do (mip of a 1 x 1 map) still loads the image library.
  measure floor bake "$exe" mip "$work/bumps1.exr" --convention +Y --threads 2 -o "$work/floor.mbk"
  for r in "${!rows[@]}"; do
    IFS='|' read -r name n args yardstick <<<"${rows[$r]}"
    read -r command rest <<<"$args"
    # memcpy+write rows (rmq builds its table while writing it): the bake and write stages, against memcpy and a
    # write and fsync of the same bytes.
    stages=bake copy_to=()
    [ "$yardstick" = memcpy+write ] && stages=bake+write copy_to=("$work/yard.bin")
    for threads in 1 2; do
      # shellcheck disable=SC2086  # the row's arguments are words
      measure "$r.$threads" $stages "$exe" "$command" "$work/bumps$n.exr" $rest --threads "$threads" \
        -o "$work/out$r.mbk"
      if [ "$yardstick" = maketx ]; then
        measure "$r.$threads.yard" bake maketx "$work/bumps$n.exr" -o "$work/out$r.tx.exr" -d float --filter box \
          --compression none --threads "$threads"
      else
        measure "$r.$threads.yard" bake "$memcpy" "$(stat -c %s "$work/out$r.mbk")" 3 "${copy_to[@]}"
        sed -i '$d' "$work/$r.$threads.yard.bake"  # the copy's own time, not the process's
        tail -1 "$work/stdout" >>"$work/$r.$threads.yard.bake"
      fi
    done
  done
done

table=""
floor=$(median "$work/floor.rss")
floor_mib=$(calc "$floor / 1024")
for r in "${!rows[@]}"; do
  IFS='|' read -r name n args yardstick <<<"${rows[$r]}"
  bytes=$(stat -c %s "$work/out$r.mbk")
  file_mib=$(calc "$bytes / 1048576")
  b1=$(median "$work/$r.1.bake") b2=$(median "$work/$r.2.bake")
  w2=$(median "$work/$r.2.wall")
  rss=$(median "$work/$r.2.rss")
  rss_mib=$(calc "$rss / 1024")
  y2=$(median "$work/$r.2.yard.bake")
  speedup=$(calc "$b1 / $b2")
  rss_ratio=$(calc "$rss_mib / $file_mib")
  above_ratio=$(calc "($rss - $floor) / 1024 / $file_mib")
  goals=()
  case "$name" in
    vmf | sh | crease)
      limit=$([ "$name" = vmf ] && echo 10 || echo 1)
      full=$([ "$name" = crease ] && echo 1024 || echo 2048)
      if [ "$n" != "$full" ]; then
        goals+=("bake <= $limit s at ${full}x${full}: not judged at ${n}x${n}")
      else
        goals+=("bake <= $limit s: $(verdict "$b2" "$limit")")
      fi
      ;;
    rmq) goals+=("bake + write <= 3x memcpy + write: $(verdict "$b2" "$(calc "3 * $y2")") ($(fmt "$(calc "$b2 / $y2")" 1)x)") ;;
    mip)
      yrss=$(median "$work/$r.2.yard.rss")
      goals+=("time <= maketx: $(verdict "$w2" "$(median "$work/$r.2.yard.wall")")")
      goals+=("peak RSS <= maketx ($(fmt "$(calc "$yrss / 1024")" 0) MiB): $(verdict "$rss" "$yrss")")
      ;;
  esac
  goals+=("2 threads >= 1.7x of 1: $(verdict 1.7 "$speedup")")
  goals+=("peak RSS above the floor <= 1.5x the file: $(verdict "$above_ratio" 1.5) ($(fmt "$above_ratio")x)")
  if [ "$yardstick" = maketx ]; then
    yard="maketx $(fmt "$(median "$work/$r.2.yard.wall")") s"
    # mip prints no stage times: the row compares whole processes (load, bake, write), as maketx's is one.
    ratio=$(calc "$w2 / $(median "$work/$r.2.yard.wall")")
  else
    yard="$yardstick $(fmt "$(calc "$y2 * 1000")" 1) ms"
    ratio=$(calc "$b2 / $y2")
  fi
  label="$name ${n}x${n}"
  [ "$name" = crease ] && label+=", $crease_segments segments"
  [ "$name" = vmf ] && label+=", 4 lobes"
  [ "$name" = sh ] && label+=", order 8"
  table+="| $label | $(fmt "$file_mib" 1) | $(fmt "$b1" 3) | $(fmt "$b2" 3) | $(fmt "$speedup") | $yard | $(fmt "$ratio" 1)x |"
  table+=" $(fmt "$rss_mib" 0) ($(fmt "$rss_ratio" 2)x; above the floor $(fmt "$above_ratio" 2)x) | $(IFS=';'; echo "${goals[*]}" | sed 's/;/; /g') |"$'\n'
done

cpu=$(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //')
report=$(cat <<EOF
# Bake speed against memory speed (generated by scripts/bench.sh; edit the script, not this file)

Machine: $(hostname), $(nproc) cores, $cpu, $(awk '/MemTotal/ {printf "%.1f GiB", $2 / 1048576}' /proc/meminfo);
load average $(cut -d' ' -f1-3 /proc/loadavg) when the table was written (the machine is shared: absolute
times are inflated, the ratios within one run much less so). Command: \`$([ -n "${BENCH_ROWS:-}" ] && echo "BENCH_ROWS=\"$BENCH_ROWS\" ")$([ -n "${BENCH_VMF_SIZE:-}" ] && echo "BENCH_VMF_SIZE=$BENCH_VMF_SIZE ")bash scripts/bench.sh$([ $quick = 1 ] && echo " --quick") $build\`
(Release build), medians of $runs interleaved runs, each run going once through every row.

Inputs: \`microbake gen bumps --size N\` (.exr, f32); the crease row adds random straight curves
(\`scripts/random-curves.py\`). "bake" is the command's own bake stage (its summary line: after loading, before
writing; mip prints none, so its row is the whole process, as is maketx's; rmq builds its table's levels while
writing them, so its row is the bake and write stages). "2 vs 1" is the bake time with \`--threads 1\` over that with
\`--threads 2\`. The yardstick runs beside each bake in every run: memcpy of as many bytes as the output file into
fresh pages (\`tests/bench/memcpy_bench.cpp\`; for rmq, memcpy+write: each copy also written to a file and fsynced,
as the bake's output is), or for mip \`maketx -d float --filter box
--compression none\` with the same threads on the same map (OpenImageIO $(maketx --help 2>&1 | sed -n 's/.*OpenImageIO \([0-9.]*\).*/\1/p' | head -1)).
Peak RSS is of the 2-thread process, with its ratio to the output file, whole and above the process's floor:
the floor, $(fmt "$floor_mib" 0) MiB here, is the peak RSS of a bake with nothing to do (\`microbake mip\` of a 1 x 1 map),
measured in the same runs. Nearly all of it is the image library: Debian's OpenImageIO loads its whole dependency
tree (260 shared libraries: OpenVDB, GDAL, DCMTK, GDCM, OpenCV, FFmpeg, ...) and runs their static initialisers before its first call (123 MiB at
the start of \`main\` of a program that only links it; \`oiiotool\` and \`maketx\` pay it too); microbake loads it only when
a command reads or writes an image. It does not grow with the map, so the "1.5x the file" goal is judged above it.

| bake | file MiB | bake s, 1 thread | bake s, 2 threads | 2 vs 1 | yardstick (2 threads) | bake / yardstick | peak RSS MiB (/ file) | goals |
|---|---|---|---|---|---|---|---|---|
${table}
EOF
)
if [ $quick = 1 ] || [ -n "${BENCH_ROWS:-}" ]; then
  echo "$report"
else
  echo "$report" >examples/results/BENCH.md
  echo "bench: wrote examples/results/BENCH.md" >&2
fi
