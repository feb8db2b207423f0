#!/usr/bin/env bash
# What accuracy costs in time (issue 12, part 3): one error-against-time frontier per technique, against brute
# force. For each technique that renders through an effect - filtering (mip, toksvig, sh orders, vmf lobes on
# examples/scenes/filtering_plane.json and filtering_spheres.json with `gen bumps`), glints (glints.json),
# colormap (colormap.json), crease (crease.json) and the demo (demo.json) - it bakes each setting's assets,
# renders the effect at 1, 4 and 16 samples per pixel and `render --reference N` (brute force: N x N rays with
# the raw maps) at N = 1, 2, 4, 8, 16 where affordable (32 for glints), and measures each render's time (the time
# `render` prints: scene, maps and assets loaded and the image rendered; process start-up and image writing
# excluded) and its RMSE (`microbake compare --format json`) against a converged reference (`--reference R
# --seed 101`, R = 64 for the filtering scenes and the demo, whose best settings came within 1.5x of a 16 x 16
# reference's floor; crease 16, colormap 12, glints 64; its noise floor is a second one with `--seed 102` against it).
# Writes, under examples/results/frontier/, one plot per scene (RMSE against time and against asset bytes,
# log-log, gnuplot) and a labelled picture strip per scene (oiiotool --text), and the overview
# examples/results/README.md with the measured tables and, per technique, where the effect beats brute force at
# equal time (scripts/frontier_verdicts.py). Some scenes are rendered smaller than their example (camera scale
# below) to keep the run near 12 minutes on the shared 2-core machine.
#
#   nice -n 5 bash scripts/report-frontier.sh [BUILD_DIR [TECHNIQUE...]]   # default build/, every technique
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
only=("${@:2}") # technique ids to measure again (default: all); the page is written from every .dat present
exe="$build/microbake"
results=examples/results
out=$results/frontier
[ -x "$exe" ] || { echo "report-frontier: $exe not found (build first: scripts/build.sh $build)" >&2; exit 2; }
bash scripts/install-deps.sh gnuplot-nox openimageio-tools fonts-dejavu-core
font=/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out" "$work/generated"

# The maps the scenes name under ../generated/, made here (the example scripts' commands and seeds).
for kind in bumps leather panels; do "$exe" gen "$kind" --size 256 --seed 1 -q -o "$work/generated/$kind.png"; done
"$exe" gen bumps --size 256 -q -o "$work/generated/filtering.png"
"$exe" gen scratches --size 512 --seed 1 -q -o "$work/generated/scratches512.png"
"$exe" gen flakes --size 512 --seed 1 -q -o "$work/generated/flakes512.png"
"$exe" gen panels --size 256 --seed 1 -q -o "$work/generated/panels256.png" --creases "$work/generated/panels256.creases.json"

# variant SCENE SCALE CHANGE OUT: SCENE with its camera's image size times SCALE, its relative paths made absolute
# (../generated/ pointing at the maps made above), and CHANGE applied to every material: "keep" (the scene's own
# effects), "none" (no effect: plain MIP-mapped normal mapping), "set:JSON" (JSON merged into each effect object),
# or an effect's JSON (that effect alone). Prints the bytes of the source files the brute force reads (normal maps,
# crease curves, colour maps).
variant() {
  python3 - "$@" "$work/generated" <<'PY'
import json, math, os, sys
scene, scale, change, out, generated = sys.argv[1:6]
folder = os.path.dirname(os.path.abspath(scene))
source_bytes = 0
def absolute(p):
    global source_bytes
    if p.startswith("../generated/"):
        p = os.path.join(generated, p[len("../generated/"):])
    p = p if os.path.isabs(p) else os.path.normpath(os.path.join(folder, p))
    source_bytes += os.path.getsize(p)
    return p
def fix(node):
    if isinstance(node, dict):
        return {k: absolute(v) if k in ("path", "curves", "colormap") and isinstance(v, str) else fix(v)
                for k, v in node.items()}
    if isinstance(node, list):
        return [fix(v) for v in node]
    return node
s = fix(json.load(open(scene)))
factor = float(scale.rstrip("crop"))
s["camera"]["width"] = round(s["camera"]["width"] * factor)
s["camera"]["height"] = round(s["camera"]["height"] * factor)
if scale.endswith("crop"):  # the centre of the view at the example's pixel size: a narrower field of view
    s["camera"]["fov_y"] = math.degrees(2 * math.atan(math.tan(math.radians(s["camera"]["fov_y"]) / 2) * factor))
for m in s["materials"].values():
    if change == "none":
        m["effects"] = []
    elif change.startswith("set:"):
        m["effects"] = [dict(e, **json.loads(change[4:])) for e in m["effects"]]
    elif change != "keep":
        m["effects"] = [json.loads(change)]
json.dump(s, open(out, "w"), indent=1)
print(source_bytes)
PY
}

# render_time ARGS...: runs `microbake render ARGS` and prints the seconds it reports.
render_time() { "$exe" render "$@" --progress never | sed -n 's/.*, \([0-9.]*\) s$/\1/p'; }
# rmse IMAGE REFERENCE [BLOCK]: RMSE per pixel, or of the means of BLOCK x BLOCK pixel blocks (box resize).
rmse() {
  local a=$1 b=$2
  if [ -n "${3:-}" ]; then
    local size
    size=$(python3 -c 'import json, sys; c = json.load(open(sys.argv[1]))["camera"]; print("%dx%d" % (c["width"] // int(sys.argv[2]), c["height"] // int(sys.argv[2])))' "$work/$id.json" "$3")
    oiiotool "$1" --resize:filter=box "$size" -o "$work/block_a.exr"
    oiiotool "$2" --resize:filter=box "$size" -o "$work/block_b.exr"
    a=$work/block_a.exr b=$work/block_b.exr
  fi
  "$exe" compare "$a" "$b" --format json | python3 -c 'import json, sys; print("%.5f" % json.load(sys.stdin)["rmse"])'
}

# Techniques: id | scene | camera scale | reference R | brute-force Ns | samples per pixel | settings (name=CHANGE;...)
vmf='{"name": "vmf", "tolerance": 1e-4, "lobes": '
filtering_settings="mip=\"mip\";toksvig=\"toksvig\";sh2={\"name\": \"sh\", \"order\": 2};sh4={\"name\": \"sh\", \"order\": 4}"
filtering_settings+=";sh8={\"name\": \"sh\", \"order\": 8};vmf1=${vmf}1};vmf2=${vmf}2};vmf4=${vmf}4};vmf8=${vmf}8}"
techniques=(
  "filtering_plane|examples/scenes/filtering_plane.json|1|64|1 2 4 8 16|1 4 16|$filtering_settings"
  "filtering_spheres|examples/scenes/filtering_spheres.json|1|64|1 2 4 8 16|1 4 16|$filtering_settings"
  "demo|examples/scenes/demo.json|0.5|64|1 2 4 8 16|1 4 16|mip=\"mip\";toksvig=\"toksvig\";sh4={\"name\": \"sh\", \"order\": 4};vmf4=${vmf}4};plain=none"
  "crease|examples/scenes/crease.json|0.5|16|1 2 4 8 16|1 4 16|crease=keep;plain=none"
  "colormap|examples/scenes/colormap.json|0.4|12|1 2 4 8|1 4 16|filtered=keep;naive=set:{\"mode\": \"naive\"}"
  "glints|examples/scenes/glints.json|0.25crop|64|1 2 4 8 16 32|1 4 16|glints=keep;plain=none"
)

ids=" ${techniques[*]%%|*} "
for name in "${only[@]}"; do
  [[ "$ids" == *" $name "* ]] || { echo "report-frontier: unknown technique '$name' (one of:$ids)" >&2; exit 2; }
done

# Glints are sub-pixel sparkles: per pixel, two 16 x 16 references differ by about their own RMSE, so their error
# is the RMSE of 6 x 6 pixel block means (how much light lands where), against a 64 x 64 reference.
declare -A block=([glints]=6)

# plot_frontier ID DATA PNG SIZE REF_N FLOOR Y_LOW BRUTE_NS [BLOCK]: RMSE against render time and against bytes read,
# every setting's samples per pixel joined by a line, brute force's N x N rays likewise, the reference's noise
# floor dashed; the legend once, beside the bytes plot.
plot_frontier() {
  local id=$1 data=$2 png=$3 size=$4 ref_n=$5 floor=$6 y_low=$7 brute_ns=$8 metric="RMSE"
  [ -n "${9:-}" ] && metric="RMSE of $9 x $9 pixel block means"
  gnuplot <<EOG
set terminal pngcairo size 1200,460 font "DejaVu Sans,9" noenhanced
set output "$png"
set multiplot title "$id ($size pixels): $metric against --reference ${ref_n}x${ref_n} (lower is better)"
set logscale xy
set grid
set linetype 1 lc rgb "#1f77b4"; set linetype 2 lc rgb "#ff7f0e"; set linetype 3 lc rgb "#2ca02c"
set linetype 4 lc rgb "#d62728"; set linetype 5 lc rgb "#9467bd"; set linetype 6 lc rgb "#8c564b"
set linetype 7 lc rgb "#e377c2"; set linetype 8 lc rgb "#17becf"; set linetype 9 lc rgb "#bcbd22"
set yrange [$y_low:*]
set arrow 1 from graph 0, first $floor to graph 1, first $floor nohead dt 2 lc rgb "gray40"
set ylabel "$metric (linear radiance)"
set tmargin at screen 0.9
set bmargin at screen 0.12
set lmargin at screen 0.07
set rmargin at screen 0.40
unset key
set xlabel "render time (s, as render prints it); lines join 1, 4, 16 samples per pixel"
plot "$data" index 0 using 3:4 with linespoints lw 3 lc rgb "black" pt 7 ps 1.3, \\
     for [i=1:*] "$data" index i using 3:4 with linespoints lw 1.5 lt i pt (i+3) ps 1.2
set lmargin at screen 0.47
set rmargin at screen 0.73
set key at screen 0.99, 0.88 right top samplen 2
set format x "%.0s %cB"
set xlabel "bytes read (baked assets; brute force, plain: the source maps)"
plot "$data" index 0 using 5:4 with linespoints lw 3 lc rgb "black" pt 7 ps 1.3 title "brute force, N x N rays (N = ${brute_ns// /, })", \\
     for [i=1:*] "$data" index i using 5:4 with linespoints lw 1.5 lt i pt (i+3) ps 1.2 title columnheader(1), \\
     NaN with lines dt 2 lc rgb "gray40" title "reference noise floor"
unset multiplot
EOG
}

for entry in "${techniques[@]}"; do
  IFS='|' read -r id scene scale ref_n brute_ns spps settings <<<"$entry"
  if [ ${#only[@]} -gt 0 ] && [[ ! " ${only[*]} " == *" $id "* ]]; then continue; fi
  data="$out/$id.dat"
  technique_start=$(date +%s)
  source_bytes=$(variant "$scene" "$scale" keep "$work/$id.json")
  ref_s=$(render_time "$work/$id.json" --reference "$ref_n" --seed 101 -o "$work/$id.ref.exr")
  render_time "$work/$id.json" --reference "$ref_n" --seed 102 -o "$work/$id.ref2.exr" >/dev/null
  floor=$(rmse "$work/$id.ref2.exr" "$work/$id.ref.exr" "${block[$id]:-}")
  size=$(python3 -c 'import json, sys; c = json.load(open(sys.argv[1]))["camera"]; print("%dx%d" % (c["width"], c["height"]))' "$work/$id.json")
  {
    echo "# technique $id scene $scene size $size reference $ref_n reference_seconds $ref_s floor $floor" \
      "block ${block[$id]:-1} load $(cut -d' ' -f1 /proc/loadavg) date $(date -u +%Y-%m-%dT%H:%MZ)"
    echo "# setting samples seconds rmse bytes"
  } >"$data"
  echo "report-frontier: $id ($size) reference ${ref_n}x$ref_n $ref_s s, floor $floor" >&2
  block() { printf '\n\n"%s"\n' "$1" >>"$data"; }
  echo '"brute force"' >>"$data"
  for n in $brute_ns; do
    t=$(render_time "$work/$id.json" --reference "$n" -o "$work/$id.brute$n.exr")
    echo "brute $n $t $(rmse "$work/$id.brute$n.exr" "$work/$id.ref.exr" "${block[$id]:-}") $source_bytes" >>"$data"
  done
  IFS=';' read -r -a setting_list <<<"$settings"
  for setting in "${setting_list[@]}"; do
    name="${setting%%=*}"
    variant "$scene" "$scale" "${setting#*=}" "$work/$id.$name.json" >/dev/null
    mkdir -p "$work/$id.$name.assets"
    "$exe" bake "$work/$id.$name.json" --out-dir "$work/$id.$name.assets" -q
    bytes=$(find "$work/$id.$name.assets" -name '*.mbk' -printf '%s\n' | awk '{ s += $1 } END { print s + 0 }')
    [ "$bytes" -gt 0 ] || bytes=$source_bytes # no asset: the render reads the source maps
    block "$name"
    for spp in $spps; do
      t=$(render_time "$work/$id.$name.json" --assets "$work/$id.$name.assets" --spp "$spp" -o "$work/$id.$name.$spp.exr")
      e=$(rmse "$work/$id.$name.$spp.exr" "$work/$id.ref.exr" "${block[$id]:-}")
      echo "$name $spp $t $e $bytes" >>"$data"
      echo "report-frontier: $id $name $spp spp: $t s, rmse $e, $bytes bytes" >&2
    done
  done

  echo "# measured_seconds $(( $(date +%s) - technique_start ))" >>"$data"

  # Picture strip: the reference, brute force at 2 x 2 rays and every setting at 4 samples per pixel, each
  # labelled under its panel.
  strip=("$work/$id.ref.exr|reference ${ref_n}x${ref_n}" "$work/$id.brute2.exr|brute force 2x2")
  for setting in "${setting_list[@]}"; do strip+=("$work/$id.${setting%%=*}.4.exr|${setting%%=*} 4 spp"); done
  panels=()
  w=${size%x*}
  h=${size#*x}
  for i in "${!strip[@]}"; do
    IFS='|' read -r image label <<<"${strip[$i]}"
    oiiotool "$image" --clamp:min=0:max=1 --colorconvert linear sRGB --fullsize "${w}x$((h + 18))" --croptofull \
      --text:x=4:y=$((h + 14)):size=13:color=1,1,1:font="$font" "$label" -d uint8 -o "$work/panel$i.png"
    panels+=("$work/panel$i.png")
  done
  columns=$(( ${#panels[@]} < 6 ? ${#panels[@]} : 6 ))
  rows=$(( (${#panels[@]} + columns - 1) / columns ))
  oiiotool "${panels[@]}" --mosaic:pad=2 "${columns}x$rows" -o "$out/${id}_strip.png"
done

# The plots, from every technique's data (also those not measured again in this run).
for data in "$out"/*.dat; do
  read -r id size ref_n floor side y_low brute_ns < <(python3 - "$data" <<'PY'
import sys
lines = open(sys.argv[1]).read().splitlines()
words = lines[0][2:].split()
h = dict(zip(words[0::2], words[1::2]))
brute = [l.split()[1] for l in lines if l.startswith("brute ")]
low = min([float(h["floor"])] + [float(l.split()[3]) for l in lines if l and l[0] not in '#"'])
print(h["technique"], h["size"], h["reference"], h["floor"], h.get("block", "1"), 0.7 * low, " ".join(brute))
PY
  )
  [ "$side" = 1 ] && side=""
  plot_frontier "$id" "$data" "$out/$id.png" "$size" "$ref_n" "$floor" "$y_low" "$brute_ns" "$side"
done

python3 scripts/frontier_verdicts.py "$out" "$results/README.md" \
  --machine "$(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //')" \
  --command "nice -n 5 bash scripts/report-frontier.sh $build"
echo "report-frontier: wrote $results/README.md and $out/"
