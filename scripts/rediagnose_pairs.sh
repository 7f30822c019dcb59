#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Diagnoses self-test pairs, then each "explained" pair again against the twin.json the first
# diagnosis wrote (docs/diagnose.md, "The improved twin"), and prints one row per pair: its truth,
# the first verdict and the second. The pairs come from the blind self-tests: the twin's own
# (`--reality twin`), the alternative reality's (`--reality alt`) or the third's (`--reality
# third`, shapes drawn at random), the last two simulators the method never fitted to; their
# sessions are given their start times, as their self-tests give them.
#
#   bash scripts/rediagnose_pairs.sh --reality twin|alt|third --seed S --from K --to L [--duration D]
#        [--build-dir DIR] [--work DIR] [--jobs N]
#
# --duration (twin only) shortens the sessions; --jobs runs that many pairs at once (default 2).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build"
reality=twin
seed=1
from=1
to=10
duration=0
jobs=2
work=""
while [ $# -gt 0 ]; do
  case "$1" in
    --reality) reality="$2"; shift 2 ;;
    --seed) seed="$2"; shift 2 ;;
    --from) from="$2"; shift 2 ;;
    --to) to="$2"; shift 2 ;;
    --duration) duration="$2"; shift 2 ;;
    --build-dir) build="$2"; shift 2 ;;
    --work) work="$2"; shift 2 ;;
    --jobs) jobs="$2"; shift 2 ;;
    *) echo "rediagnose_pairs.sh: unknown argument '$1' (valid: --reality, --seed, --from, --to, --duration, --build-dir, --work, --jobs)" >&2; exit 2 ;;
  esac
done
# The date each reality's sensor was calibrated: a session starts its age after it
# (diagnose/alt_check/alt_selftest.cpp and third_selftest.cpp).
case "$reality" in
  twin) calibrated="" ;;
  alt) calibrated="2026-01-01" ;;
  third) calibrated="2026-03-01" ;;
  *) echo "rediagnose_pairs.sh: --reality must be twin, alt or third, not '$reality'" >&2; exit 2 ;;
esac
flange="$build/flange"
[ -x "$flange" ] || { echo "rediagnose_pairs.sh: $flange not found (build the flange target)" >&2; exit 1; }
work="${work:-$(mktemp -d)}"
mkdir -p "$work"

# One pair: its sessions, the first diagnosis and, when explained, the second against its twin.json.
one_pair() {
  local k="$1" dir="$work/$reality-$seed-$1" real heldout truth
  local -a starts=()
  mkdir -p "$dir"
  if [ "$reality" = twin ]; then
    local -a length=()
    [ "$duration" != 0 ] && length=(--duration "$duration")
    "$flange" diagnose --selftest --case "$k" --seed "$seed" "${length[@]}" --bootstrap 20 \
      --out "$dir/pair" > /dev/null
    real="$dir/pair/case_${k}_calibration.csv"
    heldout="$dir/pair/case_${k}_heldout.csv"
    truth="$(python3 -c 'import json,sys; c=json.load(open(sys.argv[1]))["cases"][0]; print("+".join(e["name"] for e in c["truth"]) or c["kind"])' \
      "$dir/pair/selftest.json")"
  else
    "$flange" diagnose --selftest --reality "$reality" --case "$k" --seed "$seed" --bootstrap 20 \
      --out "$dir/pair" > /dev/null
    real="$dir/pair/pair_${k}_fit.csv"
    heldout="$dir/pair/pair_${k}_heldout.csv"
    read -r truth fit_start heldout_start < <(python3 - "$dir/pair/pair_${k}_truth.json" "$calibrated" <<'PY'
import datetime, json, sys
t = json.load(open(sys.argv[1]))
calibrated = datetime.datetime.fromisoformat(sys.argv[2]).replace(tzinfo=datetime.timezone.utc)
def start(session):
    at = calibrated + datetime.timedelta(seconds=session["start_age_s"])
    return at.strftime("%Y-%m-%dT%H:%M:%S.%fZ")
names = "+".join(e["class"] for e in t["truth"]) or t["kind"]
print(names, start(t["fit_session"]), start(t["heldout_session"]))
PY
)
    starts=(--real-start "$fit_start" --holdout-start "$heldout_start")
  fi
  "$flange" diagnose --real "$real" --holdout "$heldout" "${starts[@]}" --bootstrap 20 \
    --out "$dir/first" > /dev/null
  local first second="-"
  first="$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["verdict"]["status"])' "$dir/first/diagnosis.json")"
  if [ "$first" = explained ]; then
    "$flange" diagnose --real "$real" --holdout "$heldout" "${starts[@]}" --bootstrap 20 \
      --twin "$dir/first/twin.json" --out "$dir/second" > /dev/null
    second="$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["verdict"]["status"])' "$dir/second/diagnosis.json")"
  fi
  printf '%s\t%s\t%s\t%s\n' "$k" "$truth" "$first" "$second" > "$dir/row.tsv"
}
export -f one_pair
export work reality seed duration flange calibrated

seq "$from" "$to" | xargs -P "$jobs" -I{} bash -c 'one_pair "$@"' _ {}
printf 'pair\ttruth\tfirst\tagainst twin.json\n'
for k in $(seq "$from" "$to"); do cat "$work/$reality-$seed-$k/row.tsv"; done
python3 - "$work" "$reality" "$seed" "$from" "$to" <<'PY'
import sys
work, reality, seed, lo, hi = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4]), int(sys.argv[5])
rows = [open(f"{work}/{reality}-{seed}-{k}/row.tsv").read().split("\t") for k in range(lo, hi + 1)]
explained = [r for r in rows if r[2] == "explained"]
none = [r for r in explained if r[3].strip() == "none"]
print(f"explained: {len(explained)} of {len(rows)}; none against twin.json: {len(none)} of {len(explained)}")
PY
