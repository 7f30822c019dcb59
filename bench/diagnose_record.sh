#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The diagnosis's before-and-after record: runs one flange binary over a fixed list of pairs and
# keeps every output that says what the diagnosis decided (diagnosis.json, twin.json, the
# self-tests' JSON and tables, the printed summaries), so that a change meant to keep behaviour
# can show it did: record with the binary before the change and with the one after, then compare.
#
#   bash bench/diagnose_record.sh record --flange BUILD/flange --out DIR [--jobs N]
#   bash bench/diagnose_record.sh compare DIR_BEFORE DIR_AFTER
#
# The list (one folder and one printed summary per entry under DIR; sessions/ holds the CSVs the
# single pairs read, made by the binary under record):
#   demo            the demo's pair (temp_offset_drift, seeds 3 and 4), default bootstrap: a
#                   library pick, held in twin.json as the library effect
#   holdout_frac    one session of an ageing, its last quarter held out (--holdout-fraction 0.25:
#                   one clock)
#   start_times     an ageing across two sessions a day and a half apart (docs/diagnose_figures.md,
#                   "Ageing across two sessions"), with --real-start and --holdout-start
#   clocks_unknown  the same pair without start times (the free ageing places the held-out session)
#   free_shape      a 6 Hz pair with a voltage gain step half-way (outside the library: the free
#                   pass runs every family; free shapes picked, undetermined values, classes the
#                   data cannot tell apart, held in twin.json as a table)
#   vibration       a pair with mount vibration (the signatures stage: motion)
#   quantisation    a pair through the 16-bit converter (the signatures stage: the grid)
#   gain_law        a gain that drifts with temperature (identify: the law's parameters and
#                   their resolution)
#   rediagnose      the demo pair again against the twin.json its first diagnosis wrote
#   rediagnose_free the free_shape pair again against its twin.json (the table replayed)
#   twin_pairs      self-test pairs of the twin's reality (seed 5, cases 1-6, 1200 s), each
#                   diagnosed and, when explained, again against its twin.json
#                   (scripts/rediagnose_pairs.sh)
#   alt_pairs       the same for pairs of the alternative reality (seed 7, pairs 1-6), each with
#                   the start times of its sessions
#   selftest_twin   `diagnose --selftest` over 10 cases of 1200 s (singles, doubles, a null, two
#                   outside the library), its JSON and table
#   selftest_alt    `diagnose --selftest --reality alt` over 10 pairs (singles, a double, two
#                   nulls, one outside), its JSON and table
# record then checks that each entry still reaches the stage it is on the list for (reached.txt,
# one line per claim) and exits 1 when one does not: the record would no longer cover that stage.
#
# compare: every JSON file is read with its "generated_by" fields (and, in selftest.json, each
# case's run time "seconds") dropped and the record folder's path replaced by "<record>", then
# written sorted; the text outputs (.txt, .md, .tsv) are
# compared with the same path replaced and the self-tests' run time ("aims met (34 s)") masked;
# every CSV by its SHA-256; report.html and version.txt are not compared. Prints the files that
# differ and a unified diff of the first lines; exit status 0 when both records are the same, 1
# when any file differs, 2 on bad arguments.
set -euo pipefail

usage() {
  echo "usage: diagnose_record.sh record --flange FLANGE --out DIR [--jobs N] |" \
       "compare DIR_BEFORE DIR_AFTER" >&2
  exit 2
}

# The single pairs' sessions, made by the binary under record (the simulator is part of what a
# change could alter, and a difference there shows first in these CSVs).
simulate_sessions() {
  local flange="$1" sims="$2"
  local drift="temp_offset_drift:offset_v_per_c=-0.002"
  "$flange" simulate --scenario bench --effect "$drift" --seed 3 --out "$sims/drift_a.csv"
  "$flange" simulate --scenario bench --effect "$drift" --seed 4 --out "$sims/drift_b.csv"
  "$flange" simulate --scenario bench --effect ageing_drift:rate_v_per_day=0.8 --seed 11 \
    --out "$sims/age.csv"
  "$flange" simulate --scenario bench --seed 11 \
    --effect ageing_drift:rate_v_per_day=0.8,start_age_days=0.2 --out "$sims/age_first.csv"
  "$flange" simulate --scenario bench --seed 12 \
    --effect ageing_drift:rate_v_per_day=0.8,start_age_days=1.7 --out "$sims/age_later.csv"
  local seed
  for seed in 21 22; do
    "$flange" simulate --scenario bench --duration 1200 --fs 6 --seed "$seed" \
      --effect thermal_lag:tau_s=300 --out "$sims/lag_$seed.csv"
    # The voltage column times 1.04 from the middle row on (the header kept).
    awk -F, -v OFS=, 'NR == FNR { if ($1 ~ /^[0-9.]+$/) rows++; next }
      $1 !~ /^[0-9.]+$/ { print; next }
      { if (++row > rows / 2) $4 = sprintf("%.6f", $4 * 1.04); print }' \
      "$sims/lag_$seed.csv" "$sims/lag_$seed.csv" > "$sims/step_$seed.csv"
    "$flange" simulate --scenario bench --seed "$seed" --effect vibration \
      --out "$sims/vib_$seed.csv"
    "$flange" simulate --scenario bench --seed "$seed" --effect adc_quantization \
      --out "$sims/adc_$seed.csv"
    "$flange" simulate --scenario bench --seed "$seed" --effect temp_gain_drift \
      --out "$sims/gain_$seed.csv"
  done
}

# Runs "name|diagnose arguments" lines, N at once; each entry's summary goes to DIR/name.txt,
# with "exit S" appended when the diagnosis fails.
diagnose_entries() {
  local flange="$1" out="$2" jobs="$3"
  xargs -P "$jobs" -I{} bash -c '
    name="${1%%|*}"; args="${1#*|}"
    "$2" diagnose $args --out "$3/$name" > "$3/$name.txt" 2>&1 || echo "exit $?" >> "$3/$name.txt"
  ' _ {} "$flange" "$out"
}

record() {
  local flange="" out="" jobs=2
  while [ $# -gt 0 ]; do
    case "$1" in
      --flange) [ $# -ge 2 ] || usage; flange="$2"; shift 2 ;;
      --out) [ $# -ge 2 ] || usage; out="$2"; shift 2 ;;
      --jobs) [ $# -ge 2 ] || usage; jobs="$2"; shift 2 ;;
      *) echo "diagnose_record.sh: unknown argument '$1' (valid: --flange, --out, --jobs)" >&2
         exit 2 ;;
    esac
  done
  [ -n "$flange" ] && [ -n "$out" ] || usage
  [[ "$jobs" =~ ^[1-9][0-9]?$ ]] ||
    { echo "diagnose_record.sh: --jobs $jobs: a whole number from 1 to 99" >&2; exit 2; }
  [ -x "$flange" ] || { echo "diagnose_record.sh: $flange is not an executable" >&2; exit 2; }
  # The entries' arguments are split on blanks: a path with one would be split too.
  [[ ! "$(realpath -m "$out")" =~ [[:space:]] ]] ||
    { echo "diagnose_record.sh: --out $out: a path without blanks" >&2; exit 2; }
  [ ! -e "$out" ] || [ -z "$(ls -A "$out")" ] ||
    { echo "diagnose_record.sh: $out is not empty (a record goes into a new folder)" >&2; exit 2; }
  local here
  here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
  flange="$(realpath "$flange")"
  mkdir -p "$out"
  out="$(realpath "$out")"
  local sims="$out/sessions"
  mkdir -p "$sims" "$out/bin"
  # scripts/rediagnose_pairs.sh runs BUILD_DIR/flange: the binary under that name.
  ln -s "$flange" "$out/bin/flange"
  "$flange" --version > "$out/version.txt"
  simulate_sessions "$flange" "$sims" > "$out/sessions.txt"

  local start="--real-start 2026-11-20T08:00:00Z --holdout-start 2026-11-21T20:00:00Z"
  printf '%s\n' \
    "demo|--real $sims/drift_a.csv --holdout $sims/drift_b.csv" \
    "holdout_frac|--real $sims/age.csv --holdout-fraction 0.25 --bootstrap 20" \
    "start_times|--real $sims/age_first.csv --holdout $sims/age_later.csv $start --bootstrap 20" \
    "clocks_unknown|--real $sims/age_first.csv --holdout $sims/age_later.csv --bootstrap 20" \
    "free_shape|--real $sims/step_21.csv --holdout $sims/step_22.csv --bootstrap 20" \
    "vibration|--real $sims/vib_21.csv --holdout $sims/vib_22.csv --bootstrap 20" \
    "quantisation|--real $sims/adc_21.csv --holdout $sims/adc_22.csv --bootstrap 20" \
    "gain_law|--real $sims/gain_21.csv --holdout $sims/gain_22.csv --bootstrap 20" |
    diagnose_entries "$flange" "$out" "$jobs"
  printf '%s\n' \
    "rediagnose|--real $sims/drift_a.csv --holdout $sims/drift_b.csv --twin $out/demo/twin.json" \
    "rediagnose_free|--real $sims/step_21.csv --holdout $sims/step_22.csv --bootstrap 20 --twin $out/free_shape/twin.json" |
    diagnose_entries "$flange" "$out" "$jobs"

  # Self-test pairs of both realities, each diagnosed on its own (the alternative ones with the
  # start times of their sessions) and again against its twin.json, then the two self-tests as a
  # user runs them (exit status 1 when a small set misses an aim is part of the record).
  bash "$here/../scripts/rediagnose_pairs.sh" --reality twin --seed 5 --from 1 --to 6 \
    --duration 1200 --build-dir "$out/bin" --work "$out/twin_pairs" --jobs "$jobs" \
    > "$out/twin_pairs.txt"
  bash "$here/../scripts/rediagnose_pairs.sh" --reality alt --seed 7 --from 1 --to 6 \
    --build-dir "$out/bin" --work "$out/alt_pairs" --jobs "$jobs" > "$out/alt_pairs.txt"
  "$flange" diagnose --selftest --seed 9 --cases 10 --duration 1200 --jobs "$jobs" \
    --out "$out/selftest_twin" > "$out/selftest_twin.txt" 2>&1 ||
    echo "exit $?" >> "$out/selftest_twin.txt"
  "$flange" diagnose --selftest --reality alt --seed 9 --cases 10 --jobs "$jobs" \
    --out "$out/selftest_alt" > "$out/selftest_alt.txt" 2>&1 ||
    echo "exit $?" >> "$out/selftest_alt.txt"
  echo "diagnose_record: $(find "$out" -name '*.json' | wc -l) JSON files recorded in $out"
  reached "$out"
}

# Whether each entry reaches the stage it is on the list for, read from its diagnosis.json:
# one line per claim into DIR/reached.txt; status 1 when any claim fails.
reached() {
  python3 - "$1" <<'PY'
import json, os, sys
root = sys.argv[1]
def diagnosis(name):
    return json.load(open(os.path.join(root, name, "diagnosis.json")))
def free_picks(d):
    return [e["name"] for e in d["effects"] if "not the library's formula" in e["evidence"]]
def held_as(d):
    return {f["held_as"] for f in d["improved_twin"]["findings"]}
def resolved(d):
    return any(v is not None for e in d["effects"] for v in e["resolution"].values())
claims = [
    ("demo", "explained by a library pick held as the library effect",
     lambda d: d["verdict"]["status"] == "explained" and "library effect" in held_as(d)),
    ("holdout_frac", "one clock (held-out fraction) and a pick",
     lambda d: d["sessions"]["clock"] == "one clock" and d["effects"]),
    ("start_times", "start times, explained by ageing_drift",
     lambda d: d["sessions"]["clock"] == "start times"
     and d["verdict"]["status"] == "explained" and "ageing_drift" in d["verdict"]["effects"]),
    ("clocks_unknown", "unknown clocks, ageing_drift weighed",
     lambda d: d["sessions"]["clock"] == "unknown"
     and any(e["name"] == "ageing_drift" for e in d["effects"] + d["partial_effects"]
             + ([d["nearest"]] if d["nearest"] else []))),
    ("free_shape", "free shapes picked", lambda d: len(free_picks(d)) > 0),
    ("free_shape", "undetermined values", lambda d: any(e["undetermined"] for e in d["effects"])),
    ("free_shape", "classes the data cannot tell apart",
     lambda d: any(e["indistinguishable_from"] for e in d["effects"])),
    ("free_shape", "what to measure next", lambda d: len(d["next_measurement"]) > 0),
    ("free_shape", "held in twin.json as a table", lambda d: "table" in held_as(d)),
    ("vibration", "mount motion's signature",
     lambda d: any(e["name"] == "vibration" and e["noise_type"] for e in d["effects"])),
    ("quantisation", "the converter's signature",
     lambda d: any(e["name"] == "adc_quantization" and e["noise_type"] for e in d["effects"])),
    ("gain_law", "a library law with every parameter resolved",
     lambda d: d["effects"] and resolved(d) and not d["effects"][0]["undetermined"]),
    ("rediagnose", "against the improved twin: none", lambda d: d["verdict"]["status"] == "none"),
    ("rediagnose_free", "against the improved twin's table: none",
     lambda d: d["verdict"]["status"] == "none"),
]
failed = 0
with open(os.path.join(root, "reached.txt"), "w") as out:
    for name, claim, test in claims:
        try:
            ok = bool(test(diagnosis(name)))
        except (OSError, KeyError, ValueError) as error:
            ok, claim = False, f"{claim} ({type(error).__name__}: {error})"
        out.write(f"{name}\t{claim}\t{'yes' if ok else 'NO'}\n")
        if not ok:
            failed += 1
            print(f"diagnose_record: {name} no longer reaches its stage: {claim}", file=sys.stderr)
print(f"diagnose_record: {len(claims) - failed} of {len(claims)} stage claims hold (reached.txt)")
sys.exit(1 if failed else 0)
PY
}

# One record as comparable text, one line per line of each file: its path, a tab, the line.
normalised() {
  python3 - "$1" <<'PY'
import hashlib, json, os, re, sys
root = os.path.realpath(sys.argv[1])
run_time = re.compile(r"(aims (met|MISSED)) \(\d+ s\)$")
# What a run may change without the diagnosis changing: the command line with the binary's
# version, and a self-test case's run time.
def strip(value, dropped):
    if isinstance(value, dict):
        return {k: strip(v, dropped) for k, v in value.items() if k not in dropped}
    if isinstance(value, list):
        return [strip(v, dropped) for v in value]
    if isinstance(value, str):
        return value.replace(root, "<record>")
    return value
for folder, dirs, files in sorted(os.walk(root)):
    dirs.sort()
    for name in sorted(files):
        path = os.path.join(folder, name)
        rel = os.path.relpath(path, root)
        if name.endswith(".json"):
            try:
                dropped = {"generated_by"} | ({"seconds"} if name == "selftest.json" else set())
                text = json.dumps(strip(json.load(open(path)), dropped), indent=1, sort_keys=True)
            except ValueError as error:
                text = f"not JSON: {error}"
        elif name.endswith(".csv"):
            text = hashlib.sha256(open(path, "rb").read()).hexdigest()
        elif name.endswith((".txt", ".md", ".tsv")) and name != "version.txt":
            lines = open(path).read().replace(root, "<record>").splitlines()
            text = "\n".join(run_time.sub(r"\1 (<seconds> s)", line) for line in lines)
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
  if cmp -s "$a" "$b"; then
    echo "diagnose_record: the same ($(cut -f1 "$a" | sort -u | wc -l) files, $(wc -l < "$a") lines)"
    return 0
  fi
  echo "diagnose_record: the records differ in:"
  diff "$a" "$b" | grep '^[<>]' | cut -c3- | cut -f1 | sort -u | sed 's/^/  /' || true
  diff -u "$a" "$b" | head -40 || true
  return 1
}

case "${1:-}" in
  record) shift; record "$@" ;;
  compare) shift; compare "$@" ;;
  *) usage ;;
esac
