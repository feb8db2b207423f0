#!/usr/bin/env bash
# Installs the Debian 12 packages microbake needs to build, test and benchmark (openimageio-tools gives maketx,
# scripts/bench.sh's yardstick for mip; time, jq and bc the benchmark scripts), only when some are missing
# (quiet and fast when everything is there); make and GNU parallel run the `microbake plan` tests
# (tests/plan/pipelines_test.sh); python3 runs the independent .mbk reader (tests/spec_reader/) and, with
# python3-jsonschema, checks every --format json output against its JSON Schema (tests/schema/output_schemas_test.py).
# Extra package names may be passed as arguments. MICROBAKE_SLURM_TEST=1 also
# installs slurm-wlm and munge for tests/plan/slurm_test.sh, which starts a single-node Slurm as root: opt-in because
# the packages pull ~100 MB of daemons and libraries into every CI image, and the test needs root and two free ports;
# without them it is skipped with the reason.
set -euo pipefail

packages=(cmake ninja-build g++ pkg-config ccache clang-format
          libopenimageio-dev libopenexr-dev libeigen3-dev libcli11-dev nlohmann-json3-dev
          libflann-dev liblz4-dev libgtest-dev libxxhash-dev
          openimageio-tools time jq bc make parallel python3 python3-jsonschema "$@")
[ "${MICROBAKE_SLURM_TEST:-0}" = 1 ] && packages+=(slurm-wlm munge)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi
echo "install-deps: installing ${missing[*]}" >&2
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
