#!/usr/bin/env bash
# README set-up command (b): installs what is missing, builds, and runs every test with CTest.
# Pass --sanitize to build and test with AddressSanitizer + UndefinedBehaviorSanitizer in ./build-asan.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
if [ "${1:-}" = "--sanitize" ]; then
  BUILD_TYPE=RelWithDebInfo scripts/build.sh build-asan -DMICROBAKE_SANITIZE=ON
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  ctest --test-dir build-asan --output-on-failure -j "$(nproc)"
else
  scripts/build.sh build
  ctest --test-dir build --output-on-failure -j "$(nproc)"
fi
scripts/format.sh --check  # the one formatter (.clang-format, clang-format 14 on Debian 12)
