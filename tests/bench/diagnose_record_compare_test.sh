#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# bench/diagnose_record.sh compare on small hand-made records: two records that differ only in
# what a run may change (generated_by, the record's own folder, a self-test's run time) are the
# same (0); a changed value, a changed session, a file on one side only, or a run time outside a
# self-test's JSON differ (1); bad arguments give 2. Usage: diagnose_record_compare_test.sh SOURCE_DIR
set -euo pipefail
root=${1:?source dir}
script="$root/bench/diagnose_record.sh"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
failures=0

# One record in DIR, made by "flange VERSION", its self-test taking SECONDS.
make_record() {
  local dir="$1" version="$2" seconds="$3"
  mkdir -p "$dir/demo" "$dir/selftest_twin" "$dir/sessions"
  printf 't_s,clearance_mm,temp_c,voltage_v\n0.000000,1.500000,20.000000,0.998114\n' \
    > "$dir/sessions/drift_a.csv"
  cat > "$dir/demo/diagnosis.json" <<EOF
{"format": "flange-diagnosis/1", "real": "$dir/sessions/drift_a.csv",
 "verdict": {"status": "explained", "effects": ["temp_offset_drift"]},
 "how_far": {"heldout_rms_before_v": 0.1204, "heldout_rms_after_v": 0.0697},
 "improved_twin": {"file": "twin.json", "generated_by": "flange $version"}}
EOF
  cat > "$dir/demo.txt" <<EOF
verdict: explained by temp_offset_drift
  wrote $dir/demo/diagnosis.json
EOF
  cat > "$dir/selftest_twin/selftest.json" <<EOF
{"generated_by": "flange diagnose --selftest --cases 1 (flange $version)",
 "cases": [{"case": 1, "verdict": "explained", "seconds": $seconds}]}
EOF
  printf 'case 1 explained\naims met (%.0f s)\n' "$seconds" > "$dir/selftest_twin.txt"
  echo "flange $version" > "$dir/version.txt"
}

# expect STATUS NAME COMMAND...: the command's exit status is STATUS.
expect() {
  local want="$1" name="$2" got=0
  shift 2
  "$@" > "$work/out.txt" 2>&1 || got=$?
  if [ "$got" != "$want" ]; then
    echo "FAIL $name: exit $got, expected $want"
    sed 's/^/  /' "$work/out.txt"
    failures=$((failures + 1))
  else
    echo "ok   $name (exit $got)"
  fi
}

make_record "$work/a" 0.1.0 12.4
make_record "$work/b" 0.2.0-dirty 47.9
expect 0 "generated_by, folder and run time ignored" bash "$script" compare "$work/a" "$work/b"

cp -r "$work/b" "$work/value"
sed -i 's/0.0697/0.0698/' "$work/value/demo/diagnosis.json"
expect 1 "a changed value" bash "$script" compare "$work/a" "$work/value"
grep -q 'demo/diagnosis.json' "$work/out.txt" ||
  { echo "FAIL the changed file is not named"; failures=$((failures + 1)); }

cp -r "$work/b" "$work/verdict"
sed -i 's/verdict: explained/verdict: unexplained/' "$work/verdict/demo.txt"
expect 1 "a changed summary line" bash "$script" compare "$work/a" "$work/verdict"

cp -r "$work/b" "$work/session"
sed -i 's/0.998114/0.998115/' "$work/session/sessions/drift_a.csv"
expect 1 "a changed session" bash "$script" compare "$work/a" "$work/session"

cp -r "$work/b" "$work/missing"
rm "$work/missing/selftest_twin/selftest.json"
expect 1 "a file on one side only" bash "$script" compare "$work/a" "$work/missing"

cp -r "$work/b" "$work/timed"
sed -i 's/"heldout_rms_after_v"/"seconds": 3, "heldout_rms_after_v"/' "$work/timed/demo/diagnosis.json"
expect 1 "a run time outside a self-test's JSON" bash "$script" compare "$work/a" "$work/timed"

cp -r "$work/b" "$work/case"
sed -i 's/"verdict": "explained"/"verdict": "none"/' "$work/case/selftest_twin/selftest.json"
expect 1 "a self-test case's verdict" bash "$script" compare "$work/a" "$work/case"

expect 2 "one folder" bash "$script" compare "$work/a"
expect 2 "a folder that does not exist" bash "$script" compare "$work/a" "$work/none"
expect 2 "an unknown subcommand" bash "$script" contrast "$work/a" "$work/b"
expect 2 "record into a folder that is not empty" \
  bash "$script" record --flange /bin/true --out "$work/a"

expect 2 "record into a path with a blank" \
  bash "$script" record --flange /bin/true --out "$work/with blank"

[ "$failures" = 0 ] || { echo "$failures check(s) failed"; exit 1; }
echo "diagnose_record compare: every check passed"
