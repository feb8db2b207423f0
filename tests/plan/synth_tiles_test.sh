#!/usr/bin/env bash
# `microbake plan --synth` (issue 14 part 2: synthesis windows planned as tiles), run by the real tools: a window of
# a self-loop graph with an odd origin, a negative coordinate and sides that are not multiples of the tile, planned
# as tiles and run by ninja and by GNU parallel; every tile must equal, pixel for pixel, the same rectangle of the
# whole window synthesized by one `microbake synth` (oiiotool cuts it out; `--diff` with zero tolerance). A second
# ninja does nothing; a changed seed re-synthesizes every tile (ninja compares commands). A Slurm script with
# --lines-per-task covers every command once. Exit 77 (CTest: skipped) when ninja, parallel or oiiotool is absent.
# Usage: tests/plan/synth_tiles_test.sh MICROBAKE_EXE
set -euo pipefail
exe=$(realpath "$1")
for tool in ninja parallel oiiotool; do
  command -v "$tool" >/dev/null || { echo "SKIPPED: $tool is not installed (scripts/install-deps.sh)"; exit 77; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }

"$exe" gen bumps --size 32 --seed 3 -q -o ex.png
printf '%s' '{"exemplars":[{"id":"a","path":"ex.png"}],"root":"a","edges":[{"source":"a","destination":"a","r":1}],"normal_map":true,"convention":"+Y"}' > g.json
"$exe" graph g.json -q -o g.mbk

# The whole window: origin (-37, 11), 100 x 70 at level 7, seed 5, a jitter of our own.
window=-37,11,100,70
synth_options=(--level 7 --seed 5 --jitter 1,0.5,0.25)
"$exe" synth g.mbk "${synth_options[@]}" --window=$window -q -o whole.exr

# Every tile of a plan against the rectangle it covers.
check_tiles() {  # check_tiles FOLDER EXPECTED_COUNT
  local count=0
  for tile in "$1"/g.L7.*.exr; do
    local origin=${tile##*/g.L7.}; origin=${origin%.exr}
    local x=${origin%_*} y=${origin#*_}
    local size; size=$(oiiotool --info "$tile" | grep -o '[0-9]* x *[0-9]*' | head -1 | tr -d ' ')
    local w=${size%x*} h=${size#*x}
    oiiotool whole.exr --cut "${w}x${h}+$((x + 37))+$((y - 11))" --origin +0+0 "$tile" --origin +0+0 --fail 0 \
      --diff >/dev/null || fail "tile $tile differs from the whole window's pixels"
    count=$((count + 1))
  done
  [ "$count" -eq "$2" ] || fail "expected $2 tiles in $1, found $count"
}

# ninja: tiles of 64 -> ceil(100/64) x ceil(70/64) = 2 x 2.
"$exe" plan --synth g.mbk "${synth_options[@]}" --window=$window --tile 64 --out-dir tiles_ninja -o tiles.ninja \
  --microbake "$exe" >plan.log
grep -q "(ninja, 4 synthesis tiles)" plan.log || fail "plan summary: $(cat plan.log)"
ninja -f tiles.ninja >ninja.log 2>&1 || fail "ninja: $(tail -n 5 ninja.log)"
check_tiles tiles_ninja 4
ninja -f tiles.ninja -n | grep -q "no work to do" || fail "a second ninja had work to do"
# A changed seed: the plan changes its commands, and ninja re-synthesizes every tile.
"$exe" plan --synth g.mbk --level 7 --seed 6 --jitter 1,0.5,0.25 --window=$window --tile 64 --out-dir tiles_ninja \
  -o tiles.ninja --microbake "$exe" >/dev/null
rebuilt=$(ninja -f tiles.ninja | grep -c "synth " || true)
[ "$rebuilt" -eq 4 ] || fail "after a seed change ninja re-synthesized $rebuilt of 4 tiles"

# GNU parallel over the commands format: tiles of 40 -> 3 x 2, the last column 20 wide, the last row 30 high.
"$exe" plan --synth g.mbk "${synth_options[@]}" --window=$window --tile 40 --tile-format exr --out-dir tiles_par \
  --format commands -o tiles.commands --microbake "$exe" >/dev/null
[ "$(wc -l <tiles.commands)" -eq 6 ] || fail "commands file: $(wc -l <tiles.commands) lines"
parallel -j2 --halt now,fail=1 -a tiles.commands >/dev/null 2>&1 || fail "parallel failed"
check_tiles tiles_par 6

# Slurm with 4 lines per task: 6 commands (tiles of 40) -> 2 array tasks that together run every line once.
"$exe" plan --synth g.mbk "${synth_options[@]}" --window=$window --tile 40 --out-dir tiles_slurm --format slurm \
  --lines-per-task 4 -o tiles.sbatch --microbake "$exe" >/dev/null
grep -q "^#SBATCH --array=1-2$" tiles.sbatch || fail "slurm array: $(grep array tiles.sbatch)"
for task in 1 2; do SLURM_ARRAY_TASK_ID=$task bash tiles.sbatch >/dev/null 2>&1 || fail "slurm task $task failed"; done
check_tiles tiles_slurm 6
echo "ok: the tiles written by ninja, GNU parallel and a 2-task Slurm array equal the whole window; ninja rebuilds on a seed change only"
