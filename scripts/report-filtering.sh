#!/usr/bin/env bash
# Accuracy against ground truth of the normal-map filtering effects ([Han07] Sec. 7; issue 4, section 5): renders
# examples/scenes/filtering_plane.json (a plane receding to the horizon) and filtering_spheres.json (spheres at
# three distances), footprints from ~1 texel to beyond 256, for a generated map (`gen bumps`, 256^2) and a real
# one (../shared/data/real/brushed_streaks_diagonal.png, 512^2, -Y; read in place, never copied; skipped when
# absent), with plain mip, toksvig, sh (orders 2, 4, 8, 16) and vmf (J = 1, 2, 4, 6, 8), and `render --reference`
# as the ground truth. Per method: bake time and file size (`microbake bake` of that effect alone), render time
# and RMSE against the reference (`microbake compare --format json`), on the whole image and on the plane's far
# field (the rows just below the horizon, where footprints are largest). Writes the results block of
# examples/results/filtering/REPORT.md (between its accuracy markers), the plot accuracy.png (gnuplot) and
# side-by-side pictures (oiiotool), installing gnuplot-nox and openimageio-tools through scripts/install-deps.sh.
#
#   bash scripts/report-filtering.sh [BUILD_DIR] [REFERENCE_N]   # default build/ and 16 (16 x 16 rays per pixel)
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
ref_n="${2:-16}"
exe="$build/microbake"
results=examples/results/filtering
report=$results/REPORT.md
real_map=../shared/data/real/brushed_streaks_diagonal.png
[ -x "$exe" ] || { echo "report-filtering: $exe not found (build first: scripts/build.sh $build)" >&2; exit 2; }
bash scripts/install-deps.sh gnuplot-nox openimageio-tools
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

now() { date +%s.%N; }
elapsed() { printf '%.2f' "$(echo "$(now) - $1" | bc -l)"; }
rmse() { "$exe" compare "$1" "$2" --format json | python3 -c 'import json, sys; print("%.4f" % json.load(sys.stdin)["rmse"])'; }
# The plane's far field: 24 rows from the horizon (row 66 of 144) down.
far_field() { oiiotool "$1" --cut 240x24+0+66 -o "$2"; }

# name | effect JSON
methods=(
  'mip|"mip"'
  'toksvig|"toksvig"'
  'sh2|{"name": "sh", "order": 2}'
  'sh4|{"name": "sh", "order": 4}'
  'sh8|{"name": "sh", "order": 8}'
  'sh16|{"name": "sh", "order": 16}'
  'vmf1|{"name": "vmf", "lobes": 1, "tolerance": 1e-4}'
  'vmf2|{"name": "vmf", "lobes": 2, "tolerance": 1e-4}'
  'vmf4|{"name": "vmf", "lobes": 4, "tolerance": 1e-4}'
  'vmf6|{"name": "vmf", "lobes": 6, "tolerance": 1e-4}'
  'vmf8|{"name": "vmf", "lobes": 8, "tolerance": 1e-4}'
)

# scene_for SCENE MAP CONVENTION EFFECT OUT: the example scene with its map and effect replaced.
scene_for() {
  python3 - "$@" <<'PY'
import json, os, sys
scene, path, convention, effect, out = sys.argv[1:]
s = json.load(open(scene))
for m in s["materials"].values():
    m["normal_map"] = {"path": os.path.abspath(path), "convention": convention}
    m["effects"] = [json.loads(effect)]
json.dump(s, open(out, "w"), indent=1)
PY
}

maps=("bumps|$work/bumps.png|+Y")
"$exe" gen bumps --size 256 -q -o "$work/bumps.png"
if [ -f "$real_map" ]; then
  maps+=("brushed_streaks|$real_map|-Y")
else
  echo "report-filtering: $real_map absent: the real map is skipped" >&2
fi

rows=""
data="$work/accuracy.dat"
: >"$data"
for entry in "${maps[@]}"; do
  IFS='|' read -r map path convention <<<"$entry"
  for scene in plane spheres; do
    scene_for "examples/scenes/filtering_$scene.json" "$path" "$convention" '"mip"' "$work/$map.$scene.ref.json"
    t=$(now)
    "$exe" render "$work/$map.$scene.ref.json" --reference "$ref_n" -q -o "$work/$map.$scene.ref.exr"
    echo "report-filtering: $map $scene reference (${ref_n}x$ref_n) $(elapsed "$t") s" >&2
  done
  far_field "$work/$map.plane.ref.exr" "$work/$map.plane.ref.far.exr"
  echo "\"$map\"" >>"$data"
  for m in "${methods[@]}"; do
    IFS='|' read -r name effect <<<"$m"
    for scene in plane spheres; do scene_for "examples/scenes/filtering_$scene.json" "$path" "$convention" "$effect" "$work/$map.$scene.$name.json"; done
    assets="$work/assets.$map.$name"
    t=$(now)
    "$exe" bake "$work/$map.plane.$name.json" --out-dir "$assets" -q
    bake_s=$(elapsed "$t")
    bytes=$(cat "$assets"/*.mbk | wc -c)
    declare -A render_s=() err=()
    for scene in plane spheres; do
      t=$(now)
      "$exe" render "$work/$map.$scene.$name.json" --assets "$assets" -q -o "$work/$map.$scene.$name.exr"
      render_s[$scene]=$(elapsed "$t")
      err[$scene]=$(rmse "$work/$map.$scene.$name.exr" "$work/$map.$scene.ref.exr")
    done
    far_field "$work/$map.plane.$name.exr" "$work/$map.plane.$name.far.exr"
    far=$(rmse "$work/$map.plane.$name.far.exr" "$work/$map.plane.ref.far.exr")
    rows+="| $map | $name | $bake_s | $bytes | ${render_s[plane]} | ${err[plane]} | $far | ${render_s[spheres]} | ${err[spheres]} |"$'\n'
    echo "$name $bake_s $bytes ${err[plane]} $far ${err[spheres]}" >>"$data"
    echo "report-filtering: $map $name bake ${bake_s} s, $bytes bytes, rmse plane ${err[plane]} (far $far), spheres ${err[spheres]}" >&2
  done
  printf '\n\n' >>"$data"
  # Pictures: reference | mip | toksvig | sh8 | vmf4 (sRGB-encoded PNGs, clamped like `render -o .png`).
  for scene in plane spheres; do
    oiiotool "$work/$map.$scene.ref.exr" "$work/$map.$scene.mip.exr" "$work/$map.$scene.toksvig.exr" \
      "$work/$map.$scene.sh8.exr" "$work/$map.$scene.vmf4.exr" --mosaic 5x1 --clamp:min=0:max=1 \
      --colorconvert linear sRGB -d uint8 -o "$results/${map}_$scene.png"
  done
done

# The plot: far-field RMSE of the plane against bake time and against file size, one series per map.
gnuplot <<EOG
set terminal pngcairo size 900,420 font ",9" noenhanced
set output "$results/accuracy.png"
set multiplot layout 1,2 title "Receding plane, far field: RMSE vs --reference ${ref_n}x${ref_n} (lower is better)"
set logscale x
set grid
set key top right
set ylabel "RMSE (linear radiance)"
set xlabel "bake time (s)"
plot for [i=0:*] "$data" index i using 2:5 with points pt 7 ps 1.2 title columnheader(1), \
     for [i=0:*] "$data" index i using 2:5:1 with labels offset 0.8,0.5 font ",8" notitle
set xlabel "file size (bytes)"
plot for [i=0:*] "$data" index i using 3:5 with points pt 7 ps 1.2 title columnheader(1), \
     for [i=0:*] "$data" index i using 3:5:1 with labels offset 0.8,0.5 font ",8" notitle
unset multiplot
EOG

cpu=$(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //')
block=$(cat <<EOB
<!-- accuracy:begin (generated by scripts/report-filtering.sh; edit the script, not this block) -->
## Accuracy against \`render --reference\`

Machine: $(nproc) cores, $cpu (load average $(cut -d' ' -f1 /proc/loadavg) at the end of the run; shared).
Reference: ${ref_n} x ${ref_n} rays per pixel with the raw normal map. Renders: 1 sample per pixel, 240 x 144.
Bake and render times are wall clock of the whole command (process start and map loading included), in seconds;
bytes are the baked asset's file size. RMSE of linear radiance (\`microbake compare --format json\`) over the whole
image; "far" is the plane's 24 rows below the horizon (footprints of tens to thousands of texels). vMF assets are
baked with \`tolerance\` 1e-4 (see "Bake cost": the same log-likelihood within 0.01 nats per normal as 1e-6).

| map | method | bake (s) | bytes | plane render (s) | plane RMSE | plane far RMSE | spheres render (s) | spheres RMSE |
|---|---|---|---|---|---|---|---|---|
$rows
![RMSE against bake time and file size](accuracy.png)

<!-- accuracy:end -->
EOB
)
if grep -q 'accuracy:begin' "$report"; then
  python3 - "$report" "$block" <<'PY'
import sys
path, block = sys.argv[1], sys.argv[2]
s = open(path).read()
a = s.index('<!-- accuracy:begin'); b = s.index('<!-- accuracy:end -->') + len('<!-- accuracy:end -->')
open(path, 'w').write(s[:a] + block + s[b:])
PY
else
  printf '\n%s\n' "$block" >>"$report"
fi
echo "report-filtering: wrote $report, $results/accuracy.png and the pictures"
