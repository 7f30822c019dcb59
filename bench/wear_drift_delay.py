# SPDX-License-Identifier: MIT
# The weekly estimates of bench/wear_drift_delay.sh (see there): one store copy per cut, in date
# order, each carrying the wear estimates (with the sensor flags) the previous cut's estimate kept.
import datetime
import glob
import json
import os
import shutil
import sqlite3
import subprocess
import sys

DAY = datetime.timedelta(1)


def cut_dates(truth):
    first = datetime.date.fromisoformat(truth["first_day"])
    last = first + truth["days"] * DAY
    starts = [datetime.date.fromisoformat(d["start"]) for d in truth["drifting_sensors"]]
    cut = min(starts) if starts else first + 14 * DAY
    while cut - 7 * DAY >= first + 14 * DAY:
        cut -= 7 * DAY
    while cut < first + 14 * DAY:  # a drift from the first days: the first cut two weeks in
        cut += 7 * DAY
    cuts = []
    while cut <= last:
        cuts.append(cut)
        cut += 7 * DAY
    return cuts + [last + DAY]  # the whole history


def store_at(fleet, db_name, cut, previous, work):
    """A copy of the fleet's store as it was on `cut`, with `previous`'s kept estimates."""
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    path = os.path.join(work, db_name)
    shutil.copy(os.path.join(fleet, "migrated.db"), path)
    db = sqlite3.connect(path)
    later = "SELECT id FROM runs WHERE started_at >= ?"
    for table in ("wheel_runs", "run_trace", "alarm_events"):
        db.execute(f"DELETE FROM {table} WHERE run_id IN ({later})", (cut.isoformat(),))
    db.execute("DELETE FROM runs WHERE started_at >= ?", (cut.isoformat(),))
    db.execute("DELETE FROM maintenance_events WHERE at >= ?", (cut.isoformat(),))
    if previous:
        db.execute("ATTACH DATABASE ? AS previous", (previous,))
        for table in ("wear_estimates", "wheel_estimates"):
            db.execute(f"INSERT INTO {table} SELECT * FROM previous.{table}")
    db.commit()
    db.close()
    return path


def migrated_base(fleet, db_name, flange):
    """The fleet's store opened once by `flange wear` (schema brought up to date), no estimates."""
    work = os.path.join(fleet, "cuts")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    base = os.path.join(fleet, "migrated.db")
    for name in os.listdir(fleet):  # the database and its write-ahead log, if any
        if name.startswith(db_name):
            shutil.copy(os.path.join(fleet, name), base + name[len(db_name):])
    subprocess.run([flange, "wear", "--store", "sqlite:" + base, "--out",
                    os.path.join(work, "migrate")], check=True, stdout=subprocess.DEVNULL)
    db = sqlite3.connect(base)
    db.execute("DELETE FROM wheel_estimates")
    db.execute("DELETE FROM wear_estimates")
    db.commit()
    db.close()
    return work


def weekly_flags(fleet, db_name, truth, flange):
    """Per cut: (cut, wheels the search flags or whose rate cannot be told from no wear for a
    drift, status "sensor fault", wheels latched, every wheel)."""
    work = migrated_base(fleet, db_name, flange)
    previous, seen = None, []
    for k, cut in enumerate(cut_dates(truth)):
        path = store_at(fleet, db_name, cut, previous, os.path.join(work, str(k)))
        subprocess.run([flange, "wear", "--store", "sqlite:" + path, "--out",
                        os.path.join(work, str(k), "wear")], check=True, stdout=subprocess.DEVNULL)
        wear = json.load(open(os.path.join(work, str(k), "wear", "wear.json")))
        key = lambda w: (w["locomotive"], w["axle"], w["side"])
        found = {key(w) for w in wear["wheels"]
                 if w["sensor_fault"] is not None or w["status"] == "sensor fault"}
        latched = {key(w) for w in wear["wheels"] if w["sensor_flag"] and w["sensor_flag"]["latched"]}
        seen.append((cut, found, latched, {key(w) for w in wear["wheels"]}))
        if previous:
            shutil.rmtree(os.path.dirname(previous))
        previous = path
    shutil.rmtree(work)
    for name in os.listdir(fleet):
        if name.startswith("migrated.db"):
            os.remove(os.path.join(fleet, name))
    return seen


def first_day(seen, wheel, start, which):
    for cut, found, latched, _ in seen:
        if wheel in (found if which == "found" else latched) and cut > start:
            return (cut - start).days
    return None


def main():
    out, shape, flange, prefix, db_name, truth_name = sys.argv[1:]
    rows = []
    healthy = dict(sensors=0, sensor_cuts=0, flagged_cuts=0, found_ever=0, latched_ever=0,
                   end_found=0, end_either=0)
    for fleet in sorted(glob.glob(os.path.join(out, f"{prefix}_*_{shape}"))):
        truth = json.load(open(os.path.join(fleet, truth_name)))
        seen = weekly_flags(fleet, db_name, truth, flange)
        drifting = {(d["locomotive"], d["axle"], d["side"]): d for d in truth["drifting_sensors"]}
        _, end_found, end_latched, wheels = seen[-1]
        for wheel, drift in drifting.items():
            start = datetime.date.fromisoformat(drift["start"])
            rows.append((os.path.basename(fleet), wheel, drift, first_day(seen, wheel, start, "found"),
                         first_day(seen, wheel, start, "latched"), wheel in end_found,
                         wheel in end_found or wheel in end_latched))
        for wheel in wheels - drifting.keys():
            healthy["sensors"] += 1
            healthy["sensor_cuts"] += sum(wheel in w for *_, w in seen)
            healthy["flagged_cuts"] += sum(wheel in f for _, f, _, _ in seen)
            healthy["found_ever"] += any(wheel in f for _, f, _, _ in seen)
            healthy["latched_ever"] += any(wheel in l for _, _, l, _ in seen)
            healthy["end_found"] += wheel in end_found
            healthy["end_either"] += wheel in end_found or wheel in end_latched
    report(rows, healthy)


def report(rows, healthy):
    days = lambda d: "-" if d is None else str(d)
    yes = lambda b: "yes" if b else "no"
    print("| fleet | sensor | drift (V/day) | start | flagged by the search (days after the start)"
          " | latched | flagged at the end: search alone | search or latch |")
    print("|---|---|---|---|---|---|---|---|")
    for fleet, (loco, axle, side), drift, found, latched, end_found, end_either in rows:
        print(f"| {fleet} | {loco} axle {axle} {side} | {drift['rate_v_per_day']:+.4f} | "
              f"{drift['start']} | {days(found)} | {days(latched)} | {yes(end_found)} | "
              f"{yes(end_either)} |")
    n = len(rows)
    print(f"\ndrifting sensors flagged at the end: {sum(r[5] for r in rows)} of {n} by the search "
          f"alone, {sum(r[6] for r in rows)} of {n} by the search or the latch")
    h = healthy
    print(f"healthy sensors: {h['sensors']}; flagged by the search at some cut: {h['found_ever']} "
          f"({h['flagged_cuts']} of {h['sensor_cuts']} sensor-cuts); ever latched: "
          f"{h['latched_ever']}; flagged at the end: {h['end_found']} by the search alone, "
          f"{h['end_either']} by the search or the latch")


if __name__ == "__main__":
    main()
