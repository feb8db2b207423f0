#!/usr/bin/env bash
# The image library is loaded only by commands that read or write images (libbake/image/image_io_module.h):
# 1. the microbake executable does not need OpenImageIO, directly or through another library (ldd);
# 2. a copy of the executable in a folder without the module still runs `info` and `validate` on an asset and
#    `--version` (they never load it), and commands that read an image still work from the build folder.
# Usage: image_module_test.sh MICROBAKE_EXE
set -euo pipefail
exe="$1"
fail() { echo "FAIL: $*" >&2; exit 1; }

libs=$(ldd "$exe") || fail "ldd could not read $exe"
echo "$libs" | grep -q "libc.so" || fail "ldd listed no libraries for $exe: $libs"
if echo "$libs" | grep -q "OpenImageIO"; then
  fail "$exe loads OpenImageIO at start-up (link it only into the image module): $(echo "$libs" | grep OpenImageIO)"
fi
[ -f "$(dirname "$exe")/libmicrobake_image_io.so" ] || fail "the image module is not beside $exe"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$exe" gen bumps --size 16 -q -o "$work/b.png"
"$exe" mip "$work/b.png" -q -o "$work/b.mbk"
mkdir "$work/alone"
cp "$exe" "$work/alone/microbake"
"$work/alone/microbake" --version | grep -q "^microbake " || fail "--version of a copy without the module"
"$work/alone/microbake" info "$work/b.mbk" | grep -q "kind: *mip" || fail "info of a copy without the module"
"$work/alone/microbake" validate "$work/b.mbk" >/dev/null || fail "validate of a copy without the module"
echo "ok: no OpenImageIO at start-up; info, validate and --version run without the module"
