#!/usr/bin/env bash
# Configures and builds microbake (Release, Ninja) into ./build, or into the folder given as $1 with any
# further CMake options after it (e.g. scripts/build.sh build-asan -DMICROBAKE_SANITIZE=ON). BUILD_TARGETS="a b" builds
# only those targets (and what they need).
set -euo pipefail
cd "$(dirname "$0")/.."
dir="${1:-build}"
shift || true
cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE="${BUILD_TYPE:-Release}" "$@" >/dev/null
# shellcheck disable=SC2086 # BUILD_TARGETS is a list of names
cmake --build "$dir" -j "$(nproc)" ${BUILD_TARGETS:+--target $BUILD_TARGETS}
