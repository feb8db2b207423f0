#!/usr/bin/env bash
# The exemplars of the graphs in examples/graphs/ (multiscale synthesis, issue 7): three 64 x 64 normal maps made
# by `microbake gen` into examples/generated/ (not committed: generated, deterministic).
#
#   examples/make_synth_exemplars.sh [MICROBAKE]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
exe="${1:-${MICROBAKE:-$here/../build/microbake}}"
[[ -x "$exe" ]] || { echo "make_synth_exemplars.sh: no microbake binary at '$exe'" >&2; exit 2; }
mkdir -p "$here/generated"
"$exe" gen bumps --size 64 --seed 1 -q -o "$here/generated/synth_bumps64.png"
"$exe" gen leather --size 64 --seed 2 -q -o "$here/generated/synth_leather64.png"
"$exe" gen scratches --size 64 --seed 3 -q -o "$here/generated/synth_scratches64.png"
