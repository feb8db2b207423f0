#!/usr/bin/env bash
# The local simulation of a batch bake at scale (docs/commands/plan.md "Baking a large library"; issue 14 part 5): a library of
# MAPS procedural maps (6 kinds x seeds, SIZE x SIZE), one scene per map whose materials call for 6 assets each (mip,
# lut, rmq, sh order 4 and 6, vmf), planned once and baked three ways with two workers of one thread each:
#   bake --jobs 2 --threads 2      one microbake process (the reference)
#   ninja -j2 (OMP_NUM_THREADS=1)  one process per asset, from `plan --format ninja`
#   parallel -j2 (OMP_NUM_THREADS=1) one process per asset, from `plan --format commands`
# It prints the wall times and checks that the three asset folders hold the same files, byte for byte.
# Usage: scripts/simulate-batch.sh [BUILD_DIR [MAPS [SIZE]]]   (default: build 36 64 -> 216 assets)
set -euo pipefail
build=$(realpath "${1:-build}")
maps=${2:-36}
size=${3:-64}
exe="$build/microbake"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
mkdir -p maps scenes
kinds=(bumps brushed scratches flakes leather panels)
scenes=()
for ((i = 0; i < maps; i++)); do
  kind=${kinds[i % 6]}
  name="$kind$((i / 6 + 1))"
  "$exe" gen "$kind" --size "$size" --seed $((i / 6 + 1)) -o "maps/$name.png" -q
  cat > "scenes/$name.json" <<JSON
{"camera": {"position": [0, 1.5, 3], "look_at": [0, 0, 0], "fov_y": 45, "width": 16, "height": 12},
 "shapes": [{"type": "plane", "size": [2, 2], "material": "glints"}],
 "lights": [{"type": "point", "position": [1, 2, 1], "intensity": [4, 4, 4]}],
 "materials": {
  "glints": {"normal_map": {"path": "../maps/$name.png", "convention": "+Y"},
             "effects": [{"name": "glints", "lut_size": 256, "patch": 32}]},
  "sh4": {"normal_map": {"path": "../maps/$name.png", "convention": "+Y"}, "effects": [{"name": "sh", "order": 4}]},
  "sh6": {"normal_map": {"path": "../maps/$name.png", "convention": "+Y"}, "effects": [{"name": "sh", "order": 6}]},
  "vmf": {"normal_map": {"path": "../maps/$name.png", "convention": "+Y"},
          "effects": [{"name": "vmf", "lobes": 2, "tolerance": 1e-4}]}}}
JSON
  scenes+=("scenes/$name.json")
done

seconds() { local start=$(date +%s.%N); "$@" >/dev/null; echo "$(date +%s.%N) - $start" | bc; }
"$exe" plan "${scenes[@]}" --out-dir by_ninja --microbake "$exe" -o build.ninja >/dev/null
"$exe" plan "${scenes[@]}" --out-dir by_parallel --microbake "$exe" --format commands -o bake.commands >/dev/null
assets=$(wc -l < bake.commands)
t_bake=$(seconds "$exe" bake "${scenes[@]}" --out-dir by_bake --jobs 2 --threads 2 -q)
t_ninja=$(OMP_NUM_THREADS=1 seconds ninja -j2)
t_parallel=$(OMP_NUM_THREADS=1 seconds parallel --will-cite -j2 -a bake.commands)
for d in by_ninja by_parallel; do
  diff <(cd by_bake && ls) <(cd "$d" && ls) >/dev/null || { echo "FAIL: $d holds other files than bake's" >&2; exit 1; }
  for f in by_bake/*; do cmp -s "$f" "$d/${f#by_bake/}" || { echo "FAIL: $d/${f#by_bake/} differs" >&2; exit 1; }; done
done
bytes=$(du -sb by_bake | cut -f1)
printf '%s assets (%s maps of %sx%s, %s bytes), 2 workers x 1 thread, %s cores, load %s:\n' "$assets" "$maps" "$size" \
  "$size" "$bytes" "$(nproc)" "$(cut -d' ' -f1-3 /proc/loadavg)"
printf '  bake --jobs 2   %6.1f s (1.00x)\n' "$t_bake"
printf '  ninja -j2       %6.1f s (%.2fx)\n' "$t_ninja" "$(echo "$t_ninja / $t_bake" | bc -l)"
printf '  parallel -j2    %6.1f s (%.2fx)\n' "$t_parallel" "$(echo "$t_parallel / $t_bake" | bc -l)"
echo "  the three asset folders are byte-identical"
