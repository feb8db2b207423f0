#!/usr/bin/env bash
# The numbers and pictures of examples/results/histogram/REPORT.md ([Shah24] binned P-NDF glints under an
# environment map and a point light, examples/run_histogram.sh): for the generated scene and, when ../shared/data/real
# is beside the repository, the real-map scene, it bakes and renders the effect, the Monte Carlo reference of
# RAYS x RAYS rays (two seeds: the floor) and plain normal mapping, copies the pictures (effect | reference | plain,
# one strip per scene) into examples/results/histogram/, and prints Markdown tables: bake time and asset bytes per map; render time and block
# L1 (relative L1 of 8 x 8 block means against the reference) of the effect and of plain normal mapping beside the
# floor; the same per light; the environment alone at SH orders 10, 20, 40 and 60 (time and error), so the
# order's cost and accuracy read side by side; and each variant of the bins and storage (adaptive or uniform theta
# bins, [Shah24] Fig. 3) with its bake time, bytes and error against the same reference; then each map alone at
# 512^2 and 1024^2 (generated, and real when ../shared is there) with the exact table, the neural histogram and the
# MIP pyramid of histograms of the neural predictor's bytes (bake or training time, bytes, render time, block L1 and
# RMSE against its own reference), each neural asset's histogram KL per footprint side next to that pyramid (the
# non-neural baseline of equal bytes), and the neural histogram's accuracy against training time (1, 2, 5, 15 min).
#
#   bash scripts/report-histogram.sh [BUILD_DIR] [RAYS]     # default build/ (a Release build), RAYS = 16
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
rays="${2:-16}"
exe="$(pwd)/$build/microbake"
[ -x "$exe" ] || { echo "report: $exe not found (build first: scripts/build.sh $build)" >&2; exit 2; }
ninja -C "$build" bench_neural_histogram >/dev/null
bench="$(pwd)/$build/tests/bench_neural_histogram"
command -v jq >/dev/null || { echo "report: jq is needed (apt-get install jq)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
out=examples/results/histogram
mkdir -p "$out"
seconds() { sed -n 's/^rendered .*, \([0-9.]*\) s$/\1/p' | head -1; }
block_l1() { "$exe" compare "$1" "$2" --block 8 --format json | jq -r '.block_relative_l1 * 10000 | round / 10000'; }
rmse() { "$exe" compare "$1" "$2" --format json | jq -r '.rmse * 10000 | round / 10000'; }

# Variants of every histogram effect of a scene for the bins-and-storage table: name=JSON merged into the effect.
variants=('adaptive={"theta_binning": "adaptive"}' 'uniform={"theta_binning": "uniform"}')
# The histogram's storage in the map-size table (neural: the command's default training; pyramid: the exact asset
# compressed at load to a MIP pyramid of histograms of the neural predictor's bytes, the non-neural baseline).
methods=(exact neural pyramid)
scenes=(histogram)
[ -f ../shared/data/real/brushed_streaks_diagonal.png ] && scenes+=(histogram_real)
for s in "${scenes[@]}"; do
  bash examples/run_histogram.sh "$exe" "$work/$s" "examples/scenes/$s.json" "$rays" >"$work/$s.log" 2>&1
  cp "$work/$s/strip.png" "$out/${s}_strip.png"  # effect | reference | plain normal mapping
done

echo "Machine: $(nproc) cores, $(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1); load average $(cut -d' ' -f1-3 /proc/loadavg)."
echo "Command: \`bash scripts/report-histogram.sh $build $rays\` (reference: $rays x $rays rays per pixel)."
echo
echo "| scene | map | bins | asset bytes | bake (s) |"
echo "|---|---|---|---|---|"
for s in "${scenes[@]}"; do
  for f in "$work/$s"/assets/*.histogram.*.mbk; do
    info=$("$exe" info "$f" --format json)
    map=$(echo "$info" | jq -r '.metadata.inputs[0].path | split("/") | last')
    bins=$(echo "$info" | jq -r '.metadata.parameters | "\(.theta_bins) x \(.phi_bins)"')
    secs=$(/usr/bin/time -f %e "$exe" histogram --method exact "$(echo "$info" | jq -r '.metadata.inputs[0].path')" \
      --convention "$(echo "$info" | jq -r '.metadata.inputs[0].convention')" -q -o "$work/timed.mbk" 2>&1 | tail -1)
    echo "| $s | $map | $bins | $(stat -c %s "$f") | $secs |"
  done
done
echo
echo "| scene | effect render (s) | reference render (s) | plain render (s) | effect block L1 | plain block L1 | floor | effect / floor |"
echo "|---|---|---|---|---|---|---|---|"
for s in "${scenes[@]}"; do
  d="$work/$s"
  t_effect=$(grep "^rendered $d/histogram.exr" "$d.log" | seconds)
  t_reference=$(grep "^rendered $d/histogram_reference.exr" "$d.log" | seconds)
  t_plain=$(grep "^rendered $d/histogram_plain.exr" "$d.log" | seconds)
  e=$(block_l1 "$d/histogram.exr" "$d/histogram_reference.exr")
  p=$(block_l1 "$d/histogram_plain.exr" "$d/histogram_reference.exr")
  f=$(block_l1 "$d/histogram_reference_seed1.exr" "$d/histogram_reference.exr")
  echo "| $s | $t_effect | $t_reference | $t_plain | $e | $p | $f | $(printf "%.1f" "$(echo "scale=3; $e / $f" | bc)") |"
done
echo
echo "Per light (half resolution, each with its own floor):"
echo
echo "| scene | light | effect block L1 | floor | effect / floor |"
echo "|---|---|---|---|---|"
for s in "${scenes[@]}"; do
  sed -n 's/^\(environment\|point\): effect \([0-9.]*\), floor \([0-9.]*\), ratio \([0-9.]*\)$/\1 \2 \3 \4/p' \
    "$work/$s.log" | while read -r light e f r; do
    printf '| %s | %s | %.4f | %.4f | %s |\n' "$s" "$light" "$e" "$f" "$r"
  done
done
echo
echo "The environment alone (half resolution) at several SH orders of the distant lighting:"
echo
echo "| scene | SH order | effect render (s) | effect block L1 | floor | effect / floor |"
echo "|---|---|---|---|---|---|"
for s in "${scenes[@]}"; do
  d="$work/$s/environment"
  f=$(block_l1 "$d/reference_seed1.exr" "$d/reference.exr")
  for order in 10 20 40 60; do
    jq --argjson o "$order" '(.materials[].effects[]? | select(.name == "histogram") | .sh_order) = $o' \
      "$d/scene.json" >"$d/order.json"
    t=$("$exe" render "$d/order.json" --assets "$work/$s/assets" -o "$d/order$order.exr" | seconds)
    e=$(block_l1 "$d/order$order.exr" "$d/reference.exr")
    echo "| $s | $order | $t | $e | $f | $(printf "%.1f" "$(echo "scale=3; $e / $f" | bc)") |"
  done
done
echo
echo "Bins and storage, full resolution, against the same reference (bake and bytes: every asset the scene bakes,"
echo "its histogram assets and the mip baseline of each material):"
echo
echo "| scene | variant | bake (s) | asset bytes | effect render (s) | effect block L1 | floor | effect / floor |"
echo "|---|---|---|---|---|---|---|---|"
for s in "${scenes[@]}"; do
  d="$work/$s"
  f=$(block_l1 "$d/histogram_reference_seed1.exr" "$d/histogram_reference.exr")
  for variant in "${variants[@]}"; do
    name=${variant%%=*}
    v="$d/variant_$name"
    mkdir -p "$v"
    jq "(.materials[].effects[]? | select(.name == \"histogram\")) += ${variant#*=}" "$d/scene.json" >"$v/scene.json"
    b=$(/usr/bin/time -f %e "$exe" bake "$v/scene.json" --out-dir "$v/assets" -q 2>&1 | tail -1)
    bytes=$(cat "$v"/assets/*.mbk | wc -c)
    t=$("$exe" render "$v/scene.json" --assets "$v/assets" -o "$v/effect.exr" | seconds)
    e=$(block_l1 "$v/effect.exr" "$d/histogram_reference.exr")
    echo "| $s | $name | $b | $bytes | $t | $e | $f | $(printf "%.1f" "$(echo "scale=3; $e / $f" | bc)") |"
  done
done
echo
echo "Map sizes: each map alone on the plane of the generated scene (its roughness texture, the environment and the"
echo "point light), tiled 20 x 20 so that footprints span 8 texels or more, against its own reference and floor; bake"
echo "(training) time and bytes of its histogram asset; RMSE per pixel beside the block L1, each with its floor:"
echo
echo "| map | size | method | bake (s) | asset bytes | effect render (s) | effect block L1 | floor | effect / floor | RMSE | RMSE floor |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
sized_maps=("scratches 512=gen:512" "scratches 1024=gen:1024")
[ -f ../shared/data/real/brushed_streaks_diagonal.png ] && sized_maps+=("brushed_streaks_diagonal=real:brushed_streaks_diagonal.png")
[ -f ../shared/data/real/brick_floor.png ] && sized_maps+=("brick_floor=real:brick_floor.png")
for entry in "${sized_maps[@]}"; do
  label=${entry%%=*}
  source=${entry#*=}
  d="$work/sized/${label// /_}"
  mkdir -p "$d"
  if [ "${source%%:*}" = gen ]; then
    map="$d/map.png" convention=+Y
    "$exe" gen scratches --size "${source#gen:}" --seed 1 -q -o "$map"
  else
    map="$(pwd)/../shared/data/real/${source#real:}" convention=-Y
  fi
  size=$(iinfo "$map" | grep -o '[0-9]\+ x \+[0-9]\+' | head -1 | tr -s ' ')
  # The map tiled 20 times across the plane (the scene's 5 x 5 m), so that most pixels' footprints span 8 texels or
  # more and read the neural histogram's network (smaller ones are counted exactly from its stored texel bins).
  jq --arg map "$map" --arg c "$convention" '.shapes |= map(select(.material == "scratched_steel") | .uv_scale = [20, 20])
    | .materials |= {scratched_steel: (.scratched_steel | .normal_map = {path: $map, convention: $c, repair: true})}' \
    "$work/histogram/scene.json" >"$d/scene.json"
  "$exe" render "$d/scene.json" --reference "$rays" -q -o "$d/reference.exr"
  "$exe" render "$d/scene.json" --reference "$rays" --seed 1 -q -o "$d/reference_seed1.exr"
  f=$(block_l1 "$d/reference_seed1.exr" "$d/reference.exr")
  rf=$(rmse "$d/reference_seed1.exr" "$d/reference.exr")
  for method in "${methods[@]}"; do
    v="$d/$method"
    mkdir -p "$v"
    jq --arg m "$method" '(.materials[].effects[] | select(.name == "histogram") | .method) = $m' "$d/scene.json" >"$v/scene.json"
    b=$(/usr/bin/time -f %e "$exe" bake "$v/scene.json" --out-dir "$v/assets" -q 2>&1 | tail -1)
    bytes=$(cat "$v"/assets/*histogram*.mbk | wc -c)
    if [ "$method" = neural ]; then
      "$bench" "$v"/assets/*.neural_histogram.*.mbk "$map" "$convention" repair >"$d/kl.txt"
      { echo; echo "#### $label"; echo
        sed -e "s|^map [^,]*|map $label|" -e 's/^| side | neural KL/\n&/' "$d/kl.txt"; } >>"$work/kl.md"
    elif [ "$method" = pyramid ]; then  # the exact asset is baked; the render builds the pyramid in memory
      bytes="$(sed -n 's/^baseline: \([0-9]*\) bytes.*/\1/p' "$d/kl.txt") in memory"
    fi
    t=$("$exe" render "$v/scene.json" --assets "$v/assets" -o "$v/effect.exr" | seconds)
    e=$(block_l1 "$v/effect.exr" "$d/reference.exr")
    r=$(rmse "$v/effect.exr" "$d/reference.exr")
    echo "| $label | $size | $method | $b | $bytes | $t | $e | $f | $(printf "%.1f" "$(echo "scale=3; $e / $f" | bc)") | $r | $rf |"
  done
  rm -rf "$d"
done
echo
echo "Histogram KL per footprint side of each neural asset above (tests/bench/neural_histogram_bench.cpp: mean"
echo "D_KL(exact || predicted) over 400 footprints per side, against a MIP pyramid of histograms of the model's bytes"
echo "with trilinear interpolation, [DLW*22], and the whole map's histogram):"
cat "$work/kl.md"

# Accuracy against training time at 1024^2: one neural bake per target (1, 2, 5 and 15 minutes of wall time on this
# machine), its iterations from the per-iteration time of two short calibration bakes (their difference removes the
# exact table, k-means and held-out evaluation every bake pays once), then the same KL per side as above.
if [ -f ../shared/data/real/brick_floor.png ]; then
  curve_label=brick_floor curve_map="$(pwd)/../shared/data/real/brick_floor.png" curve_convention=-Y
else
  curve_label="scratches 1024" curve_map="$work/curve_map.png" curve_convention=+Y
  "$exe" gen scratches --size 1024 --seed 1 -q -o "$curve_map"
fi
train() {  # ITERATIONS OUT.mbk: prints the wall seconds
  /usr/bin/time -f %e "$exe" histogram --method neural "$curve_map" --convention "$curve_convention" --repair-invalid \
    --iterations "$1" -q -o "$2" 2>&1 | tail -1
}
t_short=$(train 200 "$work/curve.mbk")
t_long=$(train 1200 "$work/curve.mbk")
per_iteration=$(echo "scale=6; ($t_long - $t_short) / 1000" | bc)
fixed=$(echo "scale=3; $t_short - 200 * $per_iteration" | bc)
echo
echo "Accuracy against training time ($curve_label, 1024^2, 9 x 32 bins, F = 16, batch 512): one bake per target"
echo "wall time, its iterations from two calibration bakes on this machine ($(printf %.6f "$per_iteration") s per iteration, $(printf %.3f "$fixed") s"
echo "paid once per bake); mean D_KL(exact || predicted) per footprint side, 400 footprints each (the bench above):"
echo
echo "| target | iterations | wall (s) | 8 | 16 | 32 | 64 | 128 | 256 |"
echo "|---|---|---|---|---|---|---|---|---|"
for minutes in 1 2 5 15; do
  iterations=$(echo "($minutes * 60 - $fixed) / $per_iteration" | bc)
  wall=$(train "$iterations" "$work/curve.mbk")
  "$bench" "$work/curve.mbk" "$curve_map" "$curve_convention" repair >"$work/curve.txt"
  echo "| $minutes min | $iterations | $wall | $(awk -F'|' '/^\| [0-9]+ \|/ {printf "%s%.4f", sep, $3; sep=" | "}' "$work/curve.txt") |"
done
echo "| MIP of histograms (equal bytes) | | | $(awk -F'|' '/^\| [0-9]+ \|/ {printf "%s%.4f", sep, $4; sep=" | "}' "$work/curve.txt") |"
