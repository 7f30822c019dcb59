#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The reliability of the diagnosis's confidence (docs/diagnose.md, "Confidence"): runs the blind
# self-test on each seed and tables every claim by its confidence, in bins of 0.1, with the share
# right in each bin and among all claims at or above the bin's low end.
#   bash bench/confidence_reliability.sh REALITY SEED... [REALITY SEED...]... [-- FLANGE]
# REALITY: twin (50 cases per seed of the twin's own), alt (40 pairs per seed of the alternative
# reality) or third (40 pairs per seed of the third); seeds of several realities go into one table
# (e.g. `twin 27 28 alt 475 476 third 501 502`). FLANGE: build/flange.
# Leaves each seed's selftest.json in build/confidence_reliability/<reality><seed>/, and writes the
# table, under the command that made it, into docs/diagnose_figures.md (FIGURES=FILE writes it into
# FILE instead, FIGURES=none nowhere): between the lines "<!-- begin: COMMAND -->" and
# "<!-- end: COMMAND -->", replacing that command's earlier table, or at the end of the file.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
runs=()  # "reality seed"
reality=""
flange="$here/../build/flange"
args=()
while [ $# -gt 0 ]; do
  case "$1" in
    --) flange="$2"; break ;;
    twin | alt | third) reality="$1" ;;
    *)
      [ -n "$reality" ] ||
        { echo "confidence_reliability: seed $1 before any reality (twin, alt or third)" >&2; exit 2; }
      [[ "$1" =~ ^[0-9]+$ ]] ||
        { echo "confidence_reliability: $1 is neither a reality nor a seed" >&2; exit 2; }
      runs+=("$reality $1") ;;
  esac
  args+=("$1")
  shift
done
[ "${#runs[@]}" -gt 0 ] || { echo "confidence_reliability: give at least one seed" >&2; exit 2; }
figures="${FIGURES:-$here/../docs/diagnose_figures.md}"
command="bash bench/confidence_reliability.sh ${args[*]}"
out="$here/../build/confidence_reliability"
mkdir -p "$out"
files=()
for run in "${runs[@]}"; do
  read -r reality seed <<<"$run"
  dir="$out/$reality$seed"
  case "$reality" in
    twin) what=(--cases 50) ;;
    *) what=(--reality "$reality" --pairs 40) ;;
  esac
  "$flange" diagnose --selftest "${what[@]}" --seed "$seed" --jobs 2 --out "$dir" > "$dir.txt" ||
    true
  files+=("$dir/selftest.json")
done
table="$(mktemp)"
trap 'rm -f "$table"' EXIT
python3 - "${files[@]}" <<'PY' | tee "$table"
import json, sys
claims = []
for path in sys.argv[1:]:
    data = json.load(open(path))
    for item in data.get("pairs", data.get("cases", [])):
        claims += [(c["confidence"], c["right"]) for c in item.get("claims", [])]
print(f"{len(claims)} claims from {len(sys.argv) - 1} seed(s)")
print()
print("| confidence | claims | right | share right | claims at or above | right among them |")
print("|---|---|---|---|---|---|")
ok = True
for b in range(10):
    lo, hi = b / 10, (b + 1) / 10
    inside = [r for c, r in claims if lo <= c < hi or (b == 9 and c == 1.0)]
    above = [r for c, r in claims if c >= lo]
    share = f"{sum(inside) / len(inside):.3f}" if inside else "-"
    among = f"{sum(above) / len(above):.3f}" if above else "-"
    print(f"| {lo:.1f}-{hi:.1f} | {len(inside)} | {sum(inside)} | {share} | {len(above)} | {among} |")
    # Claims made with confidence >= p must be right at least a fraction p of the time: checked
    # at every claim's own confidence.
for c, _ in claims:
    above = [r for d, r in claims if d >= c]
    if sum(above) / len(above) < c:
        ok = False
print()
print("reliability: claims with confidence >= p are right at least p of the time:",
      "holds" if ok else "does not hold")
print("wrong claims at confidence 0.9 or more:", sum(1 for c, r in claims if c >= 0.9 and not r))
PY
[ "$figures" = none ] && exit 0
python3 - "$figures" "$command" "$table" <<'PY'
import os, sys
path, command, table = sys.argv[1], sys.argv[2], open(sys.argv[3]).read()
begin, end = f"<!-- begin: {command} -->", f"<!-- end: {command} -->"
block = f"{begin}\n\n    {command}\n\n{table.rstrip()}\n\n{end}\n"
text = open(path).read() if os.path.exists(path) else ""
if begin in text and end in text:
    head, rest = text.split(begin, 1)
    tail = rest.split(end, 1)[1].lstrip("\n")
    text = head + block + ("\n" + tail if tail else "")
else:
    text = text.rstrip("\n") + ("\n\n" if text else "") + block
open(path, "w").write(text)
print(f"confidence_reliability: the table is in {path}, under '{command}'")
PY
