#!/usr/bin/env bash
# README set-up command (b): installs what is missing, builds, and runs every test with CTest.
#   --sanitize         build ./build-asan with AddressSanitizer + UndefinedBehaviorSanitizer and run every test there.
#   --sanitize-inputs  the same build, but only what the hostile-input tests need (microbake, the corpus tests and the
#                      fuzz replays), and only those tests: the malformed-input corpus and every fuzz target's seeds
#                      and regression files (.ci/run runs this after the plain suite; docs/SANITIZERS.md).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# Leaks inside libraries, each with its reason; print_suppressions=0 keeps error output to its one line.
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/lsan_suppressions.txt:print_suppressions=0"
case "${1:-}" in
  --sanitize)
    BUILD_TYPE=RelWithDebInfo scripts/build.sh build-asan -DMICROBAKE_SANITIZE=ON
    ctest --test-dir build-asan --output-on-failure -j "$(nproc)"
    ;;
  --sanitize-inputs)
    BUILD_TYPE=RelWithDebInfo BUILD_TARGETS="microbake microbake_corpus_tests fuzz_replays" \
      scripts/build.sh build-asan -DMICROBAKE_SANITIZE=ON
    ctest --test-dir build-asan --output-on-failure -j "$(nproc)" -R '^(malformed_corpus|fuzz_regression_.*)$'
    exit 0
    ;;
  "")
    scripts/build.sh build
    ctest --test-dir build --output-on-failure -j "$(nproc)"
    ;;
  *)
    echo "run-tests.sh: unknown option '$1' (use --sanitize or --sanitize-inputs)" >&2
    exit 1
    ;;
esac
scripts/format.sh --check  # the one formatter (.clang-format, clang-format 14 on Debian 12)
