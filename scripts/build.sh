#!/usr/bin/env bash
# Configures and builds microbake (Release, Ninja) into ./build, or into the folder given as $1 with any
# further CMake options after it (e.g. scripts/build.sh build-asan -DMICROBAKE_SANITIZE=ON).
set -euo pipefail
cd "$(dirname "$0")/.."
dir="${1:-build}"
shift || true
cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE="${BUILD_TYPE:-Release}" "$@" >/dev/null
cmake --build "$dir" -j "$(nproc)"
