#!/usr/bin/env bash
# The report of multiscale synthesis from exemplar graphs ([Han08] thesis chs. 4-5; issue 7): makes the exemplars
# (examples/make_synth_exemplars.sh: 64 x 64 normal maps bumps, leather, scratches), analyses
# the graphs of examples/graphs/ (a 3-exemplar chain, a self-loop zoom, the root alone), writes the gallery
# (examples/results/synth/*.png: the chain at three levels, a zoom sequence of 16x steps, the root alone) and the
# numbers: analysis time, final-level megapixels per second on 2 threads and on 1, an 8k x 8k synthesis as 16 tiles
# of 2048 x 2048 (time, peak memory of one tile, tiles equal to the whole where they overlap a checked window), and
# the detail the chain adds over synthesis of the root alone (RMSE between a window and its 2x box blur, oiiotool),
# and the speed against a baseline revision's microbake (built into build-baseline/, ccache makes it quick): the
# same window at level 10 of the chain, synthesis plus EXR write, the two binaries run in turn three times (the
# median of each; the machine is shared), and their files compared byte for byte.
# Rewrites the synth block of examples/results/synth/REPORT.md.
#
#   bash scripts/report-synth.sh [BUILD_DIR [BASELINE_REV]]   # default build/ (a Release build) and 146033a (main
#                                                             # before issue 18's speed work); ~10 minutes on 2 cores
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/report-block.sh
build="${1:-build}"
baseline_rev="${2:-146033a}"
exe="$build/microbake"
[ -x "$exe" ] || { echo "report: $exe not found (build first: scripts/build.sh $build)" >&2; exit 2; }
command -v oiiotool >/dev/null || { echo "report: oiiotool is needed (scripts/install-deps.sh installs it)" >&2; exit 2; }
out=examples/results/synth
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"
examples/make_synth_exemplars.sh "$exe"

seconds() { sed -n 's/.* \([0-9.]*\) s (.*/\1/p'; }              # synthesis seconds from synth's summary
analysis() { sed -n 's/.*analysis \([0-9.]*\) s.*/\1/p'; }
mps() { sed -n 's/.*(\([0-9.]*\) megapixels\/s).*/\1/p'; }
for g in chain zoom root_alone; do
  line=$("$exe" graph "examples/graphs/$g.json" -o "$work/$g.mbk")
  eval "analysis_$g=$(echo "$line" | analysis)"
done

# Gallery: the same centre at every level (window centres scale by 2 per level).
window() {  # level, size, centre at level 6 (x, y) -> X,Y,W,H
  local t=$1 s=$2 scale=$((1 << ($1 - 6)))
  echo "$(( $3 * scale - s / 2 )),$(( $4 * scale - s / 2 )),$s,$s"
}
for t in 6 8 10; do "$exe" synth "$work/chain.mbk" --level $t --window "$(window $t 256 100 60)" -q -o "$out/chain_level$t.png"; done
for t in 6 10 14 18 22; do "$exe" synth "$work/zoom.mbk" --level $t --window "$(window $t 256 100 60)" -q -o "$out/zoom_level$t.png"; done
# The exemplar at its own scale (a texel a pixel, as every level of the zoom adds it), 4 x 4 tiles: 256 x 256.
bumps=examples/generated/synth_bumps64.png
oiiotool $(for i in $(seq 16); do echo "$bumps"; done) --mosaic 4x4 -o "$out/zoom_exemplar.png"
# The plateau table (issue 18): the SelfLoopZoom tests print their statistics per level and origin.
zoom_table=$("$build/tests/microbake_tests" --gtest_filter='SelfLoopZoom.*' 2>&1 | grep -E '^(bumps|leather|  level)' || true)
"$exe" synth "$work/root_alone.mbk" --level 10 --window "$(window 10 256 100 60)" -q -o "$out/root_alone_level10.png"

# Speed: a 1024 x 1024 window at level 10 of the chain, 2 threads and 1.
big=$(window 10 1024 100 60)
two=$("$exe" synth "$work/chain.mbk" --level 10 --window "$big" --threads 2 -o "$work/chain_big.exr")
one=$("$exe" synth "$work/chain.mbk" --level 10 --window "$big" --threads 1 -o "$work/chain_big1.exr")
cmp "$work/chain_big.exr" "$work/chain_big1.exr"  # the same bytes whatever the thread count
alone=$("$exe" synth "$work/root_alone.mbk" --level 10 --window "$big" -o "$work/alone_big.exr")

# Against the baseline: the baseline revision's sources in build-baseline/src (its build in build-baseline/src/build,
# so ccache's relative paths match an ordinary build), rebuilt only when the revision changes.
base_src=build-baseline/src
if [ "$(cat build-baseline/revision 2>/dev/null)" != "$(git rev-parse "$baseline_rev")" ] || [ ! -x "$base_src/build/microbake" ]; then
  rm -rf build-baseline && mkdir -p "$base_src"
  git archive "$baseline_rev" | tar -x -C "$base_src"
  cmake -S "$base_src" -B "$base_src/build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$base_src/build" --target microbake -j "$(nproc)" >/dev/null
  git rev-parse "$baseline_rev" > build-baseline/revision
fi
with_write() { sed -n 's/.*synthesis \([0-9.e-]*\) s (.*write \([0-9.e-]*\) s.*/\1 \2/p' | awk '{print $1 + $2}'; }
median() { sort -g | sed -n 2p; }
for i in 1 2 3; do
  "$base_src/build/microbake" synth "$work/chain.mbk" --level 10 --window "$big" --threads 2 -o "$work/base.exr" | with_write >> "$work/base_s"
  "$exe" synth "$work/chain.mbk" --level 10 --window "$big" --threads 2 -o "$work/now.exr" | with_write >> "$work/now_s"
done
oiiotool --fail 0 --diff "$work/base.exr" "$work/now.exr" >/dev/null  # the same pixels as the baseline (normal maps: now uncompressed EXR)
base_s=$(median < "$work/base_s")
now_s=$(median < "$work/now_s")
# Detail at the finest octave: each window against its own 2x box blur.
detail() {
  oiiotool "$1" --resize:filter=box 50% --resize:filter=triangle 200% -o "$work/blur.exr"
  "$exe" compare "$1" "$work/blur.exr" --format json | python3 -c 'import json,sys; print("%.4f" % json.load(sys.stdin)["rmse"])'
}
detail_chain=$(detail "$work/chain_big.exr")
detail_alone=$(detail "$work/alone_big.exr")

# 8k x 8k at level 10 (the scratches' own resolution: every level is synthesized, none merely magnified) as 16
# tiles of 2048 x 2048; one tile's peak memory; two tile corners against separately synthesized windows.
start=$(date +%s.%N)
peak=0
for ty in 0 1 2 3; do
  for tx in 0 1 2 3; do
    rss=$( { /usr/bin/time -f '%M' "$exe" synth "$work/chain.mbk" --level 10 --window "$((tx * 2048)),$((ty * 2048)),2048,2048" \
      -q -o "$work/tile_${tx}_${ty}.exr"; } 2>&1 | tail -1)
    [ "$rss" -gt "$peak" ] && peak=$rss
  done
done
end=$(date +%s.%N)
tiles_s=$(python3 -c "print('%.0f' % ($end - $start))")
oiiotool "$work/tile_0_0.exr" --cut 8x8+2040+2040 --origin +0+0 --fullpixels -o "$work/seam_a.exr"
oiiotool "$work/tile_1_1.exr" --cut 8x8+0+0 --origin +0+0 --fullpixels -o "$work/seam_d.exr"
"$exe" synth "$work/chain.mbk" --level 10 --window 2040,2040,8,8 -q -o "$work/seam_w.exr"
seam=$("$exe" compare "$work/seam_a.exr" "$work/seam_w.exr" --format json | python3 -c 'import json,sys; print(json.load(sys.stdin)["max_abs"])')
"$exe" synth "$work/chain.mbk" --level 10 --window 2048,2048,8,8 -q -o "$work/seam_w2.exr"
seam2=$("$exe" compare "$work/seam_d.exr" "$work/seam_w2.exr" --format json | python3 -c 'import json,sys; print(json.load(sys.stdin)["max_abs"])')

cpu=$(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //')
load=$(cut -d' ' -f1 /proc/loadavg)
block=$(cat <<EOB
<!-- synth:begin (generated by scripts/report-synth.sh; edit the script, not this block) -->
## Numbers

Machine: $(nproc) cores, ${cpu}; load average ${load} at the end of the run (the machine is shared: times are
upper bounds, ratios are measured in the same run). Command: \`bash scripts/report-synth.sh build\`.
Exemplars: \`microbake gen bumps|leather|scratches --size 64\` (normal maps, so every output is a unit normal map
that the other bakers read). Graphs: [chain.json](../../graphs/chain.json) (bumps -> leather r = 2 -> scratches
r = 2), [zoom.json](../../graphs/zoom.json) (bumps with a 2x self-loop), [root_alone.json](../../graphs/root_alone.json)
(bumps, no edge: what a user has without a graph). Synthesis options: the defaults (2 correction passes of 4
sub-passes, jitter 1, 0.6, 0.4, 0.3, ...).

| what | value |
|---|---|
| analysis (\`microbake graph\`), chain / zoom / root alone | ${analysis_chain} s / ${analysis_zoom} s / ${analysis_root_alone} s |
| chain, 1024 x 1024 at level 10, 2 threads | $(echo "$two" | seconds) s, $(echo "$two" | mps) megapixels/s |
| chain, 1024 x 1024 at level 10, 1 thread | $(echo "$one" | seconds) s, $(echo "$one" | mps) megapixels/s (same bytes as 2 threads) |
| chain, 1024 x 1024 at level 10, 2 threads, synthesis + EXR write (median of 3) | ${now_s} s, $(python3 -c "print('%.3f' % (1024 * 1024 / 1e6 / $now_s))") megapixels/s |
| the same with the baseline's microbake (${baseline_rev}), run in turn | ${base_s} s: this build $(python3 -c "print('%.2f' % ($base_s / $now_s))")x as fast, the same bytes |
| threads speed-up, 2 / 1 | $(python3 -c "print('%.2f' % ($(echo "$two" | mps) / $(echo "$one" | mps)))") |
| root alone, the same window | $(echo "$alone" | seconds) s, $(echo "$alone" | mps) megapixels/s |
| detail at the finest octave (RMSE of the window against its 2x box blur): chain / root alone | ${detail_chain} / ${detail_alone} ($(python3 -c "print('%.1f' % ($detail_chain / $detail_alone))")x) |
| root alone speed over the chain's, the same window | $(python3 -c "print('%.1f' % ($(echo "$alone" | mps) / $(echo "$two" | mps)))")x (past level 6 it only magnifies) |
| 8192 x 8192 at level 10 as 16 tiles of 2048 x 2048 (2 threads, one process per tile) | ${tiles_s} s in all, $(python3 -c "print('%.2f' % (8192 * 8192 / 1e6 / $tiles_s))") megapixels/s |
| peak memory of one 2048 x 2048 tile (max RSS) | $((peak / 1024)) MiB |
| tile corners against separately synthesized 8 x 8 windows (largest difference) | ${seam}, ${seam2} |

Self-loop zoom statistics (\`microbake_tests --gtest_filter='SelfLoopZoom.*'\`, tests/synth/texture_statistics.h;
96 x 96 windows, 16 x 16 blocks; plateau = block normal variance under 10% of the exemplar's median block
variance; contrast = the largest ratio of median block variances of neighbouring block columns or rows; step =
the largest mean squared step across a pixel line over the median line's):

\`\`\`
${zoom_table}
\`\`\`
<!-- synth:end -->
EOB
)
report_block "$out/REPORT.md" synth "Multiscale texture synthesis ([Han08]): report" "$block"
echo "report: wrote $out/REPORT.md"
