#!/usr/bin/env bash
# README set-up command (a): installs what is missing, builds, then runs the main job on the built-in
# example (examples/run_example.sh): generates the example normal maps, bakes the scene's assets, renders
# it next to a brute-force reference, compares them, and prints where the outputs are.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh build
examples/run_example.sh build/microbake out/example
