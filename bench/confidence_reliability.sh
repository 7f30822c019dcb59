#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The reliability of the diagnosis's confidence (docs/diagnose.md, "Confidence"): runs the blind
# self-test on each seed and tables every claim by its confidence, in bins of 0.1, with the share
# right in each bin and among all claims at or above the bin's low end.
#   bash bench/confidence_reliability.sh alt|twin SEED... [-- FLANGE]   (FLANGE: build/flange)
# alt: 40 pairs per seed of the alternative reality; twin: 50 cases per seed of the twin's own.
# Leaves each seed's selftest.json in build/confidence_reliability/<reality><seed>/, and writes the
# table, under the command that made it, into docs/diagnose_figures.md (FIGURES=FILE writes it into
# FILE instead, FIGURES=none nowhere): between the lines "<!-- begin: COMMAND -->" and
# "<!-- end: COMMAND -->", replacing that command's earlier table, or at the end of the file.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
reality="${1:?alt or twin}"
shift
seeds=()
flange="$here/../build/flange"
while [ $# -gt 0 ]; do
  if [ "$1" = "--" ]; then flange="$2"; break; fi
  seeds+=("$1")
  shift
done
[ "${#seeds[@]}" -gt 0 ] || { echo "confidence_reliability: give at least one seed" >&2; exit 2; }
figures="${FIGURES:-$here/../docs/diagnose_figures.md}"
command="bash bench/confidence_reliability.sh $reality ${seeds[*]}"
out="$here/../build/confidence_reliability"
mkdir -p "$out"
files=()
for seed in "${seeds[@]}"; do
  dir="$out/$reality$seed"
  if [ "$reality" = alt ]; then
    "$flange" diagnose --selftest --reality alt --pairs 40 --seed "$seed" --jobs 2 --out "$dir" \
      > "$dir.txt" || true
  else
    "$flange" diagnose --selftest --cases 50 --seed "$seed" --jobs 2 --out "$dir" > "$dir.txt" || true
  fi
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
