#!/usr/bin/env bash
# Runs the libFuzzer target for the .mbk reader for $1 seconds (default 60), seeded with valid assets.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh clang libclang-rt-14-dev
scripts/build.sh build
BUILD_TYPE=RelWithDebInfo scripts/build.sh build-fuzz -DMICROBAKE_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++
corpus=build-fuzz/corpus
mkdir -p "$corpus"
build/microbake gen bumps --size 8 -o build-fuzz/seed.png --quiet
build/microbake mip build-fuzz/seed.png -o "$corpus/seed8.mbk" --quiet
build-fuzz/fuzz_reader -max_total_time="${1:-60}" -max_len=65536 "$corpus"
