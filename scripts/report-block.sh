# Sourced by the benchmark and picture scripts: keeps one generated block of a Markdown report up to date.
#
# report_block REPORT MARKER TITLE BLOCK
#   Replaces everything from "<!-- MARKER:begin" to "<!-- MARKER:end -->" in REPORT with BLOCK (which carries
#   both markers itself), or appends BLOCK after a blank line when REPORT has no such block yet. A missing
#   REPORT (and its folder) is created, starting with the heading "# TITLE".
report_block() {
  local report=$1 marker=$2 title=$3 block=$4
  mkdir -p "$(dirname "$report")"
  if [ ! -f "$report" ]; then
    printf '# %s\n\n%s\n' "$title" "$block" >"$report"
  elif grep -q "<!-- $marker:begin" "$report"; then
    python3 - "$report" "$marker" "$block" <<'PY'
import re, sys
path, marker, block = sys.argv[1:4]
text = open(path).read()
pattern = "<!-- " + re.escape(marker) + ":begin.*?<!-- " + re.escape(marker) + ":end -->"
text = re.sub(pattern, lambda m: block, text, flags=re.S)
open(path, "w").write(text)
PY
  else
    printf '\n%s\n' "$block" >>"$report"
  fi
}
