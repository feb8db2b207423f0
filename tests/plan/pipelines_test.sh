#!/usr/bin/env bash
# `microbake plan` run by the real tools (issue 14 part 2): two scenes using every baked kind (mip, lut, rmq, sh, vmf,
# crease, colormap, moments, histogram and neural_histogram, a kind whose command has another name), with a -Y map, a
# repaired map, exact non-round numbers and assets the scenes share, planned as ninja, make and commands files and run
# by ninja, make and GNU parallel. Every tool must write exactly the files `microbake bake` writes, byte for byte; a
# second ninja/make does nothing; after one effect parameter changes, ninja re-plans and bakes exactly the one new
# asset. Exit 77 (CTest: skipped) when ninja, make or parallel is absent.
# Usage: tests/plan/pipelines_test.sh MICROBAKE_EXE
set -euo pipefail
exe=$(realpath "$1")
examples=$(cd "$(dirname "$0")/../../examples" && pwd)
for tool in ninja make parallel; do
  command -v "$tool" >/dev/null || { echo "SKIPPED: $tool is not installed (scripts/install-deps.sh)"; exit 77; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
fail() { echo "FAIL: $*" >&2; [ -f tools.log ] && tail -n 20 tools.log >&2; exit 1; }

# Inputs: a bumpy map, a panel map with its crease curves, a map with one invalid texel (repaired), a colour map.
mkdir -p maps scenes
"$exe" gen bumps --size 48 -o maps/bumps.png -q
"$exe" gen panels --size 48 -o maps/panels.png --creases maps/panels.json -q
python3 - <<'PY'
import struct, zlib
# 8x8 RGB PNG of the flat normal (128,128,255) with texel (3,2) = (128,128,0): z < 0, invalid unless repaired.
rows = b""
for y in range(8):
    row = b"\x00"
    for x in range(8):
        row += bytes((128, 128, 0)) if (x, y) == (3, 2) else bytes((128, 128, 255))
    rows += row
def chunk(t, d): return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xffffffff)
png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 8, 8, 8, 2, 0, 0, 0)) + chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b"")
open("maps/broken.png", "wb").write(png)
PY
cp "$examples/colormaps/terrain.json" maps/terrain.json

scene() {  # scene NAME SH_ORDER
  cat > "scenes/$1.json" <<JSON
{"camera": {"position": [0, 1.5, 3], "look_at": [0, 0, 0], "fov_y": 45, "width": 16, "height": 12},
 "shapes": [{"type": "plane", "size": [2, 2], "material": "bumpy"}, {"type": "sphere", "radius": 0.5, "material": "panels"}],
 "lights": [{"type": "point", "position": [1, 2, 1], "intensity": [4, 4, 4]}],
 "materials": {
  "bumpy": {"normal_map": {"path": "../maps/bumps.png", "convention": "-Y"},
            "effects": [{"name": "glints", "lut_size": 64, "patch": 16, "bits": 8, "sigma_r": 0.02},
                        {"name": "sh", "order": $2, "window": "hann"}]},
  "vmf": {"normal_map": {"path": "../maps/bumps.png", "convention": "-Y"},
          "effects": [{"name": "vmf", "lobes": 2, "align": 0.3, "tolerance": 1e-4, "max_iterations": 40}]},
  "panels": {"normal_map": {"path": "../maps/panels.png"},
             "effects": [{"name": "crease", "curves": "../maps/panels.json", "band": 2.5, "smooth_iterations": 7}]},
  "broken": {"normal_map": {"path": "../maps/broken.png", "repair": true}, "effects": ["toksvig"]},
  "neural": {"normal_map": {"path": "../maps/bumps.png", "convention": "-Y"},
             "effects": [{"name": "histogram", "method": "neural", "iterations": 20, "batch": 64, "phi_bins": 8}]},
  "binned": {"normal_map": {"path": "../maps/bumps.png", "convention": "-Y"},
             "effects": [{"name": "histogram", "theta_binning": "uniform", "theta_bins": 5, "phi_bins": 8}]},
  "ground": {"effects": [{"name": "colormap", "colormap": "../maps/terrain.json", "driver": "../maps/bumps.png",
                          "table_size": [64, 16], "sigma_max": 0.3}]}}}
JSON
}
scene one 4
scene two 4
# The second scene differs only in one material's sh order: everything else is shared.
sed -i 's/"order": 4/"order": 3/' scenes/two.json

"$exe" bake scenes/one.json scenes/two.json --out-dir baked -q
expected=$(cd baked && ls | sort)
count=$(echo "$expected" | wc -l)
# one: lut, rmq, mip and sh 4 of bumps (-Y), vmf, crease and mip of panels, mip of broken, colormap, moments,
# neural_histogram and histogram of bumps; two: sh 3.
[ "$count" -eq 13 ] || fail "bake wrote $count assets, expected 13: $expected"

same_as_bake() {  # same_as_bake FOLDER TOOL
  local got
  got=$(cd "$1" && ls | grep -v '\.tmp' | sort)
  [ "$got" = "$expected" ] || fail "$2 wrote other files than bake: $got"
  for f in $expected; do cmp -s "baked/$f" "$1/$f" || fail "$2: $f differs from bake's"; done
  echo "ok: $2 wrote the $count assets bake writes, byte for byte"
}

# ninja
"$exe" plan scenes/one.json scenes/two.json --out-dir by_ninja --microbake "$exe" -o build.ninja
[ "$(grep -c '^build by_ninja/' build.ninja)" -eq "$count" ] || fail "build.ninja has not one edge per asset"
ninja -j2 >/dev/null 2>>tools.log
same_as_bake by_ninja ninja
ninja -n | grep -q "no work to do" || fail "a second ninja wants to do work"
echo "ok: a second ninja has no work to do"
before=$(cd by_ninja && stat -c '%n %Y' * | sort)
sleep 1.1
sed -i 's/"order": 4/"order": 5/' scenes/one.json
out=$(ninja -j2 2>>tools.log)
[ "$(echo "$out" | grep -c '\] sh ')" -eq 1 ] || fail "after one change ninja baked: $out"
[ "$(echo "$out" | grep -Ec '\] (mip|lut|rmq|vmf|crease|colormap|moments|histogram|neural_histogram) ')" -eq 0 ] ||
  fail "ninja rebuilt more: $out"
after=$(cd by_ninja && stat -c '%n %Y' * | sort)
[ "$(comm -13 <(echo "$before") <(echo "$after") | wc -l)" -eq 1 ] || fail "other assets were rewritten"
echo "ok: after changing one sh order, ninja re-planned and baked only that sh asset"
ninja -n | grep -q "no work to do" || fail "ninja wants work after the rebuild"
sed -i 's/"order": 5/"order": 4/' scenes/one.json

# make
"$exe" plan scenes/one.json scenes/two.json --out-dir by_make --microbake "$exe" --format make -o assets.mk
make -f assets.mk -j2 >/dev/null 2>>tools.log
same_as_bake by_make make
[ -z "$(make -f assets.mk -j2 | grep -v 'Nothing to be done\|is up to date')" ] || fail "a second make does work"
echo "ok: a second make does nothing"

# GNU parallel
"$exe" plan scenes/one.json scenes/two.json --out-dir by_parallel --microbake "$exe" --format commands -o bake.commands
[ "$(wc -l < bake.commands)" -eq "$count" ] || fail "bake.commands has not one line per asset"
parallel --will-cite --joblog jobs.log --resume-failed -j2 -a bake.commands >/dev/null 2>>tools.log
same_as_bake by_parallel parallel
[ "$(tail -n +2 jobs.log | awk '$7 != 0' | wc -l)" -eq 0 ] || fail "a parallel job failed: $(cat jobs.log)"

# slurm: the script and its commands file beside it (run by a real Slurm in tests/plan/slurm_test.sh)
mkdir -p slurm
"$exe" plan scenes/one.json scenes/two.json --out-dir by_slurm --microbake "$exe" --format slurm -o slurm/bake.sbatch
cmp -s <(sed 's/by_parallel/by_slurm/g' bake.commands) slurm/bake.commands || fail "slurm/bake.commands differs"
grep -qx "#SBATCH --array=1-$count" slurm/bake.sbatch || fail "slurm/bake.sbatch has no --array=1-$count"
for i in 1 2; do SLURM_ARRAY_TASK_ID=$i bash slurm/bake.sbatch >/dev/null 2>>tools.log; done
for i in 1 2; do f=$(sed -n "${i}p" slurm/bake.commands | sed 's/.* -o //'); cmp -s "$f" "baked/$(basename "$f")" || fail "task $i"; done
echo "ok: the Slurm script's task i runs line i (tasks 1 and 2 run by hand)"
