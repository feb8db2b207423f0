#!/usr/bin/env bash
# Formats every C++ file with the root .clang-format; with --check, changes nothing and fails when a file
# is not formatted (CI runs the check through scripts/run-tests.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
command -v clang-format >/dev/null || { echo "format: clang-format not installed (apt-get install clang-format)" >&2; exit 0; }
mapfile -t files < <(git ls-files '*.cpp' '*.h' 2>/dev/null || find cli formats libbake tests -name '*.cpp' -o -name '*.h')
if [ "${1:-}" = "--check" ]; then
  clang-format --dry-run --Werror "${files[@]}"
else
  clang-format -i "${files[@]}"
fi
