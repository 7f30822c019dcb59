#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The diagnosis's before-and-after record: runs one flange binary over a fixed list of pairs and
# keeps every output that says what the diagnosis decided (diagnosis.json, twin.json, the
# self-tests' JSON and tables), so that a change meant to keep behaviour can show it did: record
# with the binary before the change and with the one after, then compare.
#
#   bash bench/diagnose_record.sh record --flange BUILD/flange --out DIR [--jobs N]
#   bash bench/diagnose_record.sh compare DIR_BEFORE DIR_AFTER
#
# The list (one folder per entry under DIR):
#   demo            the demo's pair (temp_offset_drift, seeds 3 and 4), default bootstrap
#   holdout_frac    one session, its last quarter held out (--holdout-fraction 0.25)
#   free_shape      a 6 Hz pair with a voltage gain step half-way (outside the library: every
#                   free-shape family runs)
#   vibration       a pair with clearance vibration (the signatures stage)
#   quantisation    a pair through a coarser converter (the signatures stage)
#   gain_law        a gain that drifts with temperature (identify: the law's parameters and
#                   their resolution)
#   rediagnose      the demo pair again against the twin.json its first diagnosis wrote
#                   (the improved twin)
#   twin_pairs      self-test pairs of the twin's reality (seed 5, cases 1-6)
#   alt_pairs       pairs of the alternative reality with their start times (seed 7, pairs
#                   1-6): each diagnosed with --real-start/--holdout-start, and its self-test
#   selftest_twin   `diagnose --selftest` over 6 cases, its JSON and table
#   selftest_alt    `diagnose --selftest --reality alt` over 6 pairs, its JSON and table
#
# compare: every JSON file is read with its "generated_by" fields dropped and the record folder's
# path replaced by "<record>", then written sorted; the text outputs are compared with the same
# path replaced. Prints one line per entry that differs (and a unified diff of its first lines);
# exit status 0 when both records are the same, 1 when any entry differs, 2 on bad arguments.
set -euo pipefail

usage() {
  echo "usage: diagnose_record.sh record --flange FLANGE --out DIR [--jobs N] |" \
       "compare DIR_BEFORE DIR_AFTER" >&2
  exit 2
}

record() {
  local flange="" out="" jobs=2
  while [ $# -gt 0 ]; do
    case "$1" in
      --flange) flange="$2"; shift 2 ;;
      --out) out="$2"; shift 2 ;;
      --jobs) jobs="$2"; shift 2 ;;
      *) echo "diagnose_record.sh: unknown argument '$1' (valid: --flange, --out, --jobs)" >&2
         exit 2 ;;
    esac
  done
  [ -n "$flange" ] && [ -n "$out" ] || usage
  [ -x "$flange" ] || { echo "diagnose_record.sh: $flange is not an executable" >&2; exit 2; }
  flange="$(realpath "$flange")"
  mkdir -p "$out"
  out="$(realpath "$out")"
  local sims="$out/sessions"
  mkdir -p "$sims"
  "$flange" --version > "$out/version.txt"

  # The sessions the single pairs read (made by the binary under record: the simulator is part of
  # what a change could alter, and a difference there shows first in these CSVs).
  local drift="temp_offset_drift:offset_v_per_c=-0.002"
  "$flange" simulate --scenario bench --effect "$drift" --seed 3 --out "$sims/drift_a.csv" >/dev/null
  "$flange" simulate --scenario bench --effect "$drift" --seed 4 --out "$sims/drift_b.csv" >/dev/null
  "$flange" simulate --scenario bench --effect ageing_drift --seed 11 --out "$sims/age.csv" >/dev/null
  for seed in 21 22; do
    "$flange" simulate --scenario bench --duration 1200 --fs 6 --seed "$seed" \
      --effect thermal_lag:tau_s=300 --out "$sims/lag_$seed.csv" >/dev/null
    # The voltage column times 1.04 from the middle row on (header lines kept).
    awk -F, -v OFS=, 'NR == FNR { if ($1 ~ /^[0-9.]+$/) rows++; next }
      $1 !~ /^[0-9.]+$/ { print; next }
      { if (++row > rows / 2) $4 = sprintf("%.6f", $4 * 1.04); print }' \
      "$sims/lag_$seed.csv" "$sims/lag_$seed.csv" > "$sims/step_$seed.csv"
    "$flange" simulate --scenario bench --seed "$seed" --effect vibration \
      --out "$sims/vib_$seed.csv" >/dev/null
    "$flange" simulate --scenario bench --seed "$seed" --effect adc_quantization \
      --out "$sims/adc_$seed.csv" >/dev/null
    "$flange" simulate --scenario bench --seed "$seed" --effect temp_gain_drift \
      --out "$sims/gain_$seed.csv" >/dev/null
  done

  local -a runs=(
    "demo|--real $sims/drift_a.csv --holdout $sims/drift_b.csv"
    "holdout_frac|--real $sims/age.csv --holdout-fraction 0.25 --bootstrap 20"
    "free_shape|--real $sims/step_21.csv --holdout $sims/step_22.csv --bootstrap 20"
    "vibration|--real $sims/vib_21.csv --holdout $sims/vib_22.csv --bootstrap 20"
    "quantisation|--real $sims/adc_21.csv --holdout $sims/adc_22.csv --bootstrap 20"
    "gain_law|--real $sims/gain_21.csv --holdout $sims/gain_22.csv --bootstrap 20")
  printf '%s\n' "${runs[@]}" | xargs -P "$jobs" -I{} bash -c '
    name="${1%%|*}"; args="${1#*|}"
    "$2" diagnose $args --out "$3/$name" > "$3/$name.txt" 2>&1 || echo "exit $?" >> "$3/$name.txt"
  ' _ {} "$flange" "$out"
  "$flange" diagnose --real "$sims/drift_a.csv" --holdout "$sims/drift_b.csv" \
    --twin "$out/demo/twin.json" --out "$out/rediagnose" > "$out/rediagnose.txt" 2>&1 ||
    echo "exit $?" >> "$out/rediagnose.txt"

  # Self-test pairs of both realities, each diagnosed on its own (the alternative ones with the
  # start times of their sessions), then the two self-tests as a user runs them.
  bash "$(dirname "${BASH_SOURCE[0]}")/../scripts/rediagnose_pairs.sh" --reality twin --seed 5 \
    --from 1 --to 6 --duration 1200 --build-dir "$(dirname "$flange")" --work "$out/twin_pairs" \
    --jobs "$jobs" > "$out/twin_pairs.txt"
  bash "$(dirname "${BASH_SOURCE[0]}")/../scripts/rediagnose_pairs.sh" --reality alt --seed 7 \
    --from 1 --to 6 --build-dir "$(dirname "$flange")" --work "$out/alt_pairs" \
    --jobs "$jobs" > "$out/alt_pairs.txt"
  "$flange" diagnose --selftest --seed 9 --cases 6 --duration 1200 --jobs "$jobs" \
    --out "$out/selftest_twin" > "$out/selftest_twin.txt" 2>&1 || echo "exit $?" >> "$out/selftest_twin.txt"
  "$flange" diagnose --selftest --reality alt --seed 9 --cases 6 --jobs "$jobs" \
    --out "$out/selftest_alt" > "$out/selftest_alt.txt" 2>&1 || echo "exit $?" >> "$out/selftest_alt.txt"
  echo "diagnose_record: $(find "$out" -name '*.json' | wc -l) JSON files recorded in $out"
}

# One record as comparable text: JSON without generated_by, the record's path as <record>.
normalised() {
  python3 - "$1" <<'PY'
import json, os, sys
root = os.path.realpath(sys.argv[1])
def strip(value):
    if isinstance(value, dict):
        return {k: strip(v) for k, v in value.items() if k != "generated_by"}
    if isinstance(value, list):
        return [strip(v) for v in value]
    if isinstance(value, str):
        return value.replace(root, "<record>")
    return value
for folder, dirs, files in sorted(os.walk(root)):
    dirs.sort()
    for name in sorted(files):
        path = os.path.join(folder, name)
        rel = os.path.relpath(path, root)
        if rel.startswith("sessions" + os.sep) or name == "version.txt":
            continue
        if name.endswith(".json"):
            text = json.dumps(strip(json.load(open(path))), indent=1, sort_keys=True)
        elif name.endswith(".txt") or name.endswith(".md"):
            text = open(path).read().replace(root, "<record>")
        else:
            continue
        for line in text.splitlines():
            print(f"{rel}\t{line}")
PY
}

compare() {
  [ $# -eq 2 ] && [ -d "$1" ] && [ -d "$2" ] || usage
  local a b
  a="$(mktemp)"; b="$(mktemp)"
  trap 'rm -f "$a" "$b"' RETURN
  normalised "$1" > "$a"
  normalised "$2" > "$b"
  if diff -q "$a" "$b" > /dev/null; then
    echo "diagnose_record: the same ($(cut -f1 "$a" | sort -u | wc -l) files, $(wc -l < "$a") lines)"
    return 0
  fi
  echo "diagnose_record: the records differ in:"
  diff <(cut -f1 "$a" | sort -u) <(cut -f1 "$b" | sort -u) | sed -n 's/^[<>] /  only one side: /p'
  diff "$a" "$b" | grep '^[<>]' | cut -c3- | cut -f1 | sort -u | sed 's/^/  /'
  diff -u "$a" "$b" | head -40
  return 1
}

case "${1:-}" in
  record) shift; record "$@" ;;
  compare) shift; compare "$@" ;;
  *) usage ;;
esac
