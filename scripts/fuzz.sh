#!/usr/bin/env bash
# Fuzzes every parser (docs/TESTING.md "Fuzzing", docs/FUZZING.md): builds the libFuzzer targets of tests/fuzz/ once, in
# build-fuzz/ with clang 14 (MICROBAKE_FUZZ=ON: the libraries under test compiled with coverage feedback,
# AddressSanitizer and UndefinedBehaviorSanitizer), then runs each target in turn with one job for SECONDS (default
# 60), seeded from tests/fuzz/corpus/<name>/ (read only; inputs that add coverage go to build-fuzz/corpus/<name>/).
#
#   scripts/fuzz.sh [SECONDS [NAME...]]      NAME: asset scene graph colormap curves_json curves_svg normal_map (all)
#   FUZZ_RUNS=1000000 scripts/fuzz.sh 3600   stop each target after that many executions (or SECONDS, if sooner)
#
# Each run's libFuzzer log is build-fuzz/logs/<name>.log; one summary line per target follows. A crash, a sanitizer
# report, a leak or an input slower than 10 s leaves its input in build-fuzz/crashes/<name>/ and makes the exit
# status 1 (reproduce it: build-fuzz/tests/fuzz/fuzz_<name> FILE; then add FILE to tests/fuzz/corpus/<name>/).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
shift || true
names=("$@")

scripts/install-deps.sh clang-14 libclang-rt-14-dev libomp-14-dev
BUILD_TYPE=None scripts/build.sh build-fuzz -DMICROBAKE_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++-14
if [ ${#names[@]} -eq 0 ]; then  # every target tests/fuzz/CMakeLists.txt declares
  for exe in build-fuzz/tests/fuzz/fuzz_*; do [ -x "$exe" ] && names+=("${exe#build-fuzz/tests/fuzz/fuzz_}"); done
fi

max_len() {  # the largest input each target is given: assets hold a few sections, texts are short files
  case "$1" in
    asset | normal_map) echo 65536 ;;
    *) echo 16384 ;;
  esac
}

export OMP_NUM_THREADS=1  # one core per campaign on a shared machine; outputs do not depend on it
status=0
for name in "${names[@]}"; do
  exe="build-fuzz/tests/fuzz/fuzz_$name"
  [ -x "$exe" ] || { echo "fuzz.sh: no target '$name'" >&2; exit 1; }
  mkdir -p "build-fuzz/corpus/$name" "build-fuzz/crashes/$name" build-fuzz/logs
  log="build-fuzz/logs/$name.log"
  runs=()
  [ -n "${FUZZ_RUNS:-}" ] && runs=(-runs="$FUZZ_RUNS")
  start=$(date +%s)
  if ! "$exe" -max_total_time="$seconds" "${runs[@]}" -max_len="$(max_len "$name")" -timeout=10 -rss_limit_mb=2048 \
      -print_final_stats=1 -artifact_prefix="build-fuzz/crashes/$name/" \
      "build-fuzz/corpus/$name" "tests/fuzz/corpus/$name" >"$log" 2>&1; then
    status=1
    echo "fuzz.sh: $name FAILED (see $log and build-fuzz/crashes/$name/)" >&2
  fi
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
  ft=$(grep -o 'ft: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
  echo "fuzz $name: ${execs:-?} executions, ${cov:-?} coverage edges, ${ft:-?} features, $(($(date +%s) - start)) s"
done
exit $status
