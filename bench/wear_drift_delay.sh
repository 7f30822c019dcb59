#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# How soon `flange wear` flags a drifting sensor (docs/fleet.md, "How soon a drift is flagged"):
# for each fleet bench/wear_coverage.sh left in build/wear_coverage/, and each drifting sensor of
# its truth, a copy of the store cut after 7, 14, 21, 28 and 35 days from the drift's start (the
# runs from the cut on deleted, as if the depot looked on that day), read by `flange wear`. Prints
# the days at which each drift is first flagged and every healthy sensor flagged at any cut.
#   bash bench/wear_drift_delay.sh [LOCOMOTIVES] [DAYS] [FLANGE] [REALITY]
#   (defaults: 5, 90, build/flange, fleet)
# Run bench/wear_coverage.sh (REALITY fleet) or bench/wear_coverage_alt.sh (REALITY fleet-alt: the
# stores the service path filled) with the same LOCOMOTIVES and DAYS first.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
locomotives="${1:-5}"
days="${2:-90}"
flange="${3:-$here/../build/flange}"
reality="${4:-fleet}"
out="$here/../build/wear_coverage"
case "$reality" in
  fleet) prefix=seed; db=fleet.db; truth=fleet_truth.json ;;
  fleet-alt) prefix=alt_seed; db=store.db; truth=depot/fleet_truth.json ;;
  *) echo "REALITY: $reality is neither fleet nor fleet-alt" >&2; exit 2 ;;
esac
python3 - "$out" "${locomotives}x${days}" "$flange" "$prefix" "$db" "$truth" <<'PY'
import datetime, glob, json, os, shutil, sqlite3, subprocess, sys

out, shape, flange, prefix, db_name, truth_name = sys.argv[1:]
cuts = [7, 14, 21, 28, 35]
rows, healthy_flags = [], 0
for fleet in sorted(glob.glob(os.path.join(out, f"{prefix}_*_{shape}"))):
    truth = json.load(open(os.path.join(fleet, truth_name)))
    last = datetime.date.fromisoformat(truth["first_day"]) + datetime.timedelta(truth["days"])
    drifting = {(d["locomotive"], d["axle"], d["side"]) for d in truth["drifting_sensors"]}
    for drift in truth["drifting_sensors"]:
        start = datetime.date.fromisoformat(drift["start"])
        first_flag = None
        for days in cuts:
            cut = start + datetime.timedelta(days)
            if cut > last:
                break
            work = os.path.join(fleet, "cut")
            shutil.rmtree(work, ignore_errors=True)
            os.makedirs(work)
            for name in os.listdir(fleet):
                if name.startswith(db_name):
                    shutil.copy(os.path.join(fleet, name), work)
            db = sqlite3.connect(os.path.join(work, db_name))
            later = "SELECT id FROM runs WHERE started_at >= ?"
            for table in ("wheel_runs", "run_trace", "alarm_events"):
                db.execute(f"DELETE FROM {table} WHERE run_id IN ({later})", (cut.isoformat(),))
            db.execute("DELETE FROM runs WHERE started_at >= ?", (cut.isoformat(),))
            db.execute("DELETE FROM maintenance_events WHERE at >= ?", (cut.isoformat(),))
            db.commit()
            db.close()
            subprocess.run([flange, "wear", "--store", "sqlite:" + os.path.join(work, db_name),
                            "--out", os.path.join(work, "wear")], check=True,
                           stdout=subprocess.DEVNULL)
            wear = json.load(open(os.path.join(work, "wear", "wear.json")))
            flagged = {(w["locomotive"], w["axle"], w["side"]) for w in wear["wheels"]
                       if w["sensor_fault"] is not None}
            healthy_flags += len(flagged - drifting)
            if first_flag is None and (drift["locomotive"], drift["axle"], drift["side"]) in flagged:
                first_flag = days
        rows.append((os.path.basename(fleet), drift, first_flag))
print("| fleet | sensor | drift (V/day) | start | first flagged (days after the start) |")
print("|---|---|---|---|---|")
for fleet, drift, first_flag in rows:
    when = f"{first_flag}" if first_flag is not None else f"not within {cuts[-1]} (or the period)"
    print(f"| {fleet} | {drift['locomotive']} axle {drift['axle']} {drift['side']} | "
          f"{drift['rate_v_per_day']:+.4f} | {drift['start']} | {when} |")
print(f"\nhealthy sensors flagged over all cuts: {healthy_flags}")
PY
