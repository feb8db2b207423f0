#!/usr/bin/env bash
# Accuracy against ground truth of the normal-map filtering effects ([Han07] Sec. 7; issue 4, section 5): renders
# examples/scenes/filtering_plane.json (a plane receding to the horizon) and filtering_spheres.json (spheres at
# three distances) under point and directional lights, and the same spheres under an environment map alone (a
# lat-long EXR with band-1 and band-2 content the script makes with oiiotool: [Han07] Eq. 7.23 is what shades
# it), for a generated map (`gen bumps`, 256^2) and three real ones from ../shared/data/real/ (read in place,
# never copied; each skipped when absent): brushed_streaks_diagonal.png (anisotropic), metallic_flakes.png and
# scifi_panel_bevels.png (multi-lobe texels: flakes with their own tilts, bevels), all -Y, loaded with
# `repair` (metallic_flakes has a texel with z < 0). Methods: plain mip, toksvig, sh (orders 2, 4, 8, 16) and vmf
# (J = 1, 2, 4, 6, 8), rendered with --spp SPP (default 4: at 1 sample per pixel the spheres' error is mostly
# silhouette aliasing against the reference), and `render --reference` as the ground truth. Per method:
# bake time and file size (`microbake bake` of that effect alone), render time and RMSE against the reference
# (`microbake compare --format json`) on the whole image, on the plane's far field (the rows just below the
# horizon) and on an interior crop of each sphere (no silhouette: near ~1.5, middle ~5, far ~60 texels per
# pixel on the 256^2 map, twice that on the 512^2 ones). Writes the results block of
# examples/results/filtering/REPORT.md (between its accuracy markers), the plot accuracy.png (gnuplot) and
# side-by-side pictures (oiiotool), installing gnuplot-nox and openimageio-tools through scripts/install-deps.sh.
#
#   bash scripts/report-filtering.sh [BUILD_DIR] [REFERENCE_N] [SPP]   # default build/, 64 (64 x 64 rays), 4
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
ref_n="${2:-64}"
spp="${3:-4}"
exe="$build/microbake"
results=examples/results/filtering
report=$results/REPORT.md
real=../shared/data/real
[ -x "$exe" ] || { echo "report-filtering: $exe not found (build first: scripts/build.sh $build)" >&2; exit 2; }
bash scripts/install-deps.sh gnuplot-nox openimageio-tools
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

now() { date +%s.%N; }
elapsed() { printf '%.2f' "$(echo "$(now) - $1" | bc -l)"; }
rmse() { "$exe" compare "$1" "$2" --format json | python3 -c 'import json, sys; print("%.4f" % json.load(sys.stdin)["rmse"])'; }
# Crops (oiiotool geometry): the plane's far field, 24 rows from the horizon (row 66 of 144) down; the interior
# of each sphere (inside ~0.6 of its projected radius: no silhouette pixel).
declare -A crops=([far]=240x24+0+66 [near]=56x56+29+44 [mid]=16x16+154+58 [distant]=6x6+191+49)
crop_rmse() { # IMAGE REFERENCE CROP
  oiiotool "$1" --cut "${crops[$3]}" -o "$work/a.exr" && oiiotool "$2" --cut "${crops[$3]}" -o "$work/b.exr"
  rmse "$work/a.exr" "$work/b.exr"
}

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

# The environment: a 64 x 32 lat-long map, bright sky towards one azimuth fading to a dark ground (bands 1, 2).
oiiotool --pattern fill:topleft=2.0,1.8,1.5:topright=0.3,0.4,0.6:bottomleft=0.15,0.12,0.1:bottomright=0.02,0.02,0.03 \
  64x32 3 -d float -o "$work/environment.exr"

# scene_for SCENE MAP CONVENTION EFFECT OUT [env]: the example scene with its map and effect replaced (and with
# "env", its lights replaced by the environment map alone).
scene_for() {
  python3 - "$@" "$work/environment.exr" <<'PY'
import json, os, sys
scene, path, convention, effect, out = sys.argv[1:6]
env = sys.argv[6] == "env"
s = json.load(open(scene))
for m in s["materials"].values():
    m["normal_map"] = {"path": os.path.abspath(path), "convention": convention, "repair": True}
    m["effects"] = [json.loads(effect)]
if env:
    s["lights"] = [{"type": "environment", "path": sys.argv[-1]}]
json.dump(s, open(out, "w"), indent=1)
PY
}
scene_file() { [ "$1" = env ] && echo examples/scenes/filtering_spheres.json || echo "examples/scenes/filtering_$1.json"; }
scene_mode() { [ "$1" = env ] && echo env || echo plain; }

maps=("bumps|$work/bumps.png|+Y")
"$exe" gen bumps --size 256 -q -o "$work/bumps.png"
for real_map in brushed_streaks_diagonal metallic_flakes scifi_panel_bevels; do
  if [ -f "$real/$real_map.png" ]; then
    maps+=("$real_map|$real/$real_map.png|-Y")
  else
    echo "report-filtering: $real/$real_map.png absent: that map is skipped" >&2
  fi
done

rows=""
reference_times=""
# Plot data: one file per map and method family, "parameter bake_s bytes far_rmse" (parameter: the SH order or
# the vMF lobe count; "-" for mip and toksvig).
families=(mip toksvig sh vmf)
plot_maps=()
declare -A floor=() floor_far=()
for entry in "${maps[@]}"; do
  IFS='|' read -r map path convention <<<"$entry"
  ref_line="| $map |"
  for scene in plane spheres env; do
    scene_for "$(scene_file $scene)" "$path" "$convention" '"mip"' "$work/$map.$scene.ref.json" "$(scene_mode $scene)"
    t=$(now)
    "$exe" render "$work/$map.$scene.ref.json" --reference "$ref_n" -q -o "$work/$map.$scene.ref.exr"
    ref_line+=" $(elapsed "$t") |"
    echo "report-filtering: $map $scene reference (${ref_n}x$ref_n) $(elapsed "$t") s" >&2
    # The reference's own noise floor: a second reference with other sub-pixel rays (--seed 1).
    "$exe" render "$work/$map.$scene.ref.json" --reference "$ref_n" --seed 1 -q -o "$work/$map.$scene.ref2.exr"
    floor[$scene]=$(rmse "$work/$map.$scene.ref2.exr" "$work/$map.$scene.ref.exr")
  done
  reference_times+="$ref_line"$'\n'
  far=$(crop_rmse "$work/$map.plane.ref2.exr" "$work/$map.plane.ref.exr" far)
  near=$(crop_rmse "$work/$map.spheres.ref2.exr" "$work/$map.spheres.ref.exr" near)
  mid=$(crop_rmse "$work/$map.spheres.ref2.exr" "$work/$map.spheres.ref.exr" mid)
  distant=$(crop_rmse "$work/$map.spheres.ref2.exr" "$work/$map.spheres.ref.exr" distant)
  rows+="| $map | *reference floor* | | | | ${floor[plane]} | $far | | ${floor[spheres]} | $near | $mid | $distant | ${floor[env]} |"$'\n'
  floor_far[$map]=$far
  plot_maps+=("$map")
  for family in "${families[@]}"; do : >"$work/plot.$map.$family.dat"; done
  for m in "${methods[@]}"; do
    IFS='|' read -r name effect <<<"$m"
    for scene in plane spheres env; do
      scene_for "$(scene_file $scene)" "$path" "$convention" "$effect" "$work/$map.$scene.$name.json" "$(scene_mode $scene)"
    done
    assets="$work/assets.$map.$name"
    t=$(now)
    "$exe" bake "$work/$map.plane.$name.json" --out-dir "$assets" -q
    bake_s=$(elapsed "$t")
    bytes=$(cat "$assets"/*.mbk | wc -c)
    declare -A render_s=() err=()
    for scene in plane spheres env; do
      t=$(now)
      "$exe" render "$work/$map.$scene.$name.json" --assets "$assets" --spp "$spp" -q -o "$work/$map.$scene.$name.exr"
      render_s[$scene]=$(elapsed "$t")
      err[$scene]=$(rmse "$work/$map.$scene.$name.exr" "$work/$map.$scene.ref.exr")
    done
    far=$(crop_rmse "$work/$map.plane.$name.exr" "$work/$map.plane.ref.exr" far)
    near=$(crop_rmse "$work/$map.spheres.$name.exr" "$work/$map.spheres.ref.exr" near)
    mid=$(crop_rmse "$work/$map.spheres.$name.exr" "$work/$map.spheres.ref.exr" mid)
    distant=$(crop_rmse "$work/$map.spheres.$name.exr" "$work/$map.spheres.ref.exr" distant)
    rows+="| $map | $name | $bake_s | $bytes | ${render_s[plane]} | ${err[plane]} | $far | ${render_s[spheres]} | ${err[spheres]} | $near | $mid | $distant | ${err[env]} |"$'\n'
    family=${name%%[0-9]*} parameter=${name#"${name%%[0-9]*}"}
    echo "${parameter:--} $bake_s $bytes $far" >>"$work/plot.$map.$family.dat"
    echo "report-filtering: $map $name bake ${bake_s} s, $bytes bytes, rmse plane ${err[plane]} (far $far), spheres ${err[spheres]} ($near, $mid, $distant), env ${err[env]}" >&2
  done
  # Pictures: reference | mip | toksvig | sh8 | vmf4 (sRGB-encoded PNGs, clamped like `render -o .png`).
  for scene in plane spheres env; do
    oiiotool "$work/$map.$scene.ref.exr" "$work/$map.$scene.mip.exr" "$work/$map.$scene.toksvig.exr" \
      "$work/$map.$scene.sh8.exr" "$work/$map.$scene.vmf4.exr" --mosaic 5x1 --clamp:min=0:max=1 \
      --colorconvert linear sRGB -d uint8 -o "$results/${map}_$scene.png"
  done
done

# The plot: far-field RMSE of the plane against bake time (top row) and file size (bottom row), one column of
# panels per map (44 labelled points on one pair of axes overlapped). Each family is one series; a point's label is
# its SH order or vMF lobe count, and the dashed line is that map's reference floor.
plot_panel() { # MAP X_COLUMN
  local series="" family style offset
  for family in "${families[@]}"; do
    # SH labels below left of their points, vMF labels above right: the two series cross without their labels.
    case $family in sh) style="linespoints" offset="-0.9,-0.6" ;; vmf) style="linespoints" offset="0.9,0.5" ;;
      *) style="points" offset="0,0" ;; esac
    series+="\"$work/plot.$1.$family.dat\" using $2:4 with $style pt 7 ps 1.1 title \"$family\", "
    series+="\"$work/plot.$1.$family.dat\" using $2:4:(strcol(1) eq \"-\" ? \"\" : strcol(1)) with labels"
    series+=" offset $offset font \",8\" notitle, "
  done
  echo "set title \"$1\"; plot ${series}${floor_far[$1]} with lines dt 2 lc rgb \"gray40\" title \"reference floor\""
}
{
  echo "set terminal pngcairo size $((300 * ${#plot_maps[@]} + 80)),760 font \",9\" noenhanced"
  echo "set output \"$results/accuracy.png\""
  echo "set multiplot layout 2,${#plot_maps[@]} title \"Receding plane, far field: RMSE vs --reference ${ref_n}x${ref_n} (lower is better; labels: SH order, vMF lobes)\""
  echo "set logscale xy; set grid; set key below horizontal font \",8\"; set ylabel \"far-field RMSE\""
  echo "set xlabel \"bake time (s)\""
  for map in "${plot_maps[@]}"; do plot_panel "$map" 2; done
  echo "set xlabel \"file size (bytes)\"; set format x \"%.0e\""
  for map in "${plot_maps[@]}"; do plot_panel "$map" 3; done
  echo "unset multiplot"
} >"$work/accuracy.gnuplot"
gnuplot "$work/accuracy.gnuplot"

cpu=$(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //')
block=$(cat <<EOB
<!-- accuracy:begin (generated by scripts/report-filtering.sh; edit the script, not this block) -->
## Accuracy against \`render --reference\`

Machine: $(nproc) cores, $cpu (load average $(cut -d' ' -f1 /proc/loadavg) at the end of the run; shared).
Reference: ${ref_n} x ${ref_n} rays per pixel with the raw normal map. Renders: ${spp} samples per pixel, 240 x 144.
Bake and render times are wall clock of the whole command (process start and map loading included), in seconds;
bytes are the baked asset's file size. RMSE of linear radiance (\`microbake compare --format json\`): "plane" and
"spheres" over the whole image; "far" the plane's 24 rows below the horizon (footprints of ~7 texels at the
crop's bottom row to thousands at the horizon); "near", "mid", "distant" an interior crop of each sphere (no
silhouette pixels; ~1.5, ~5 and ~60 texels per pixel on the 256^2 map, twice that on the 512^2 maps); "env" the
spheres lit by an environment map alone (bands 0-2, [Han07] Eq. 7.23), whole image. vMF assets are baked with
\`tolerance\` 1e-4 (see "Bake cost": the same log-likelihood within 0.01 nats per normal as 1e-6). Each map's
first row, *reference floor*, is a second reference with other sub-pixel rays (\`--seed 1\`) against the first:
no method can be measured below it.

Reference render times (s), ${ref_n} x ${ref_n} rays per pixel:

| map | plane | spheres | env spheres |
|---|---|---|---|
$reference_times
| map | method | bake (s) | bytes | plane render (s) | plane RMSE | plane far RMSE | spheres render (s) | spheres RMSE | near sphere | mid sphere | distant sphere | env spheres RMSE |
|---|---|---|---|---|---|---|---|---|---|---|---|---|
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
