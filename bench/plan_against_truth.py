#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# The reprofiling plan (docs/fleet.md, "Reprofiling plan") against the second reality's true
# critical dates (sim/fleet_alt/fleet_alt_limits.h): for each fleet in
# build/wear_coverage/alt_seed_S_5x120/ (store.db and depot/fleet_truth.json, as
# bench/wear_coverage_alt.sh leaves them), a copy of its store is estimated by `flange wear`
# (which keeps the estimates), then planned from the kept estimates at each risk with a horizon
# past every date; a wheel reaches the critical clearance first when its true critical date is
# before its due date. Prints, per risk, the wheels planned, how many reach it first (the share
# should be the risk) and how many are due after their own forecast critical date.
#   python3 bench/plan_against_truth.py FLANGE "RISKS" SEEDS...
import csv
import io
import json
import pathlib
import shutil
import subprocess
import sys
import tempfile

HORIZON = "2099-01-01"


def truth_dates(path):
    truth = json.loads(path.read_text())
    return {(loco["name"], int(w["axle"]), w["side"]): w.get("true_critical_date", "")
            for loco in truth["locomotives"] for w in loco["wheels"]}


def plan_rows(flange, store, out, risk):
    done = subprocess.run([flange, "wear", "--store", store, "--out", str(out), "--plan",
                           "--before", HORIZON, "--risk", str(risk), "--plan-csv", "-"],
                          check=True, capture_output=True, text=True)
    if "not re-estimated" not in done.stderr:
        sys.exit(f"{store}: the plan was not made from the kept estimates:\n{done.stderr}")
    return list(csv.DictReader(io.StringIO(done.stdout)))


def main():
    flange, risks, seeds = sys.argv[1], [float(r) for r in sys.argv[2].split()], sys.argv[3:]
    root = pathlib.Path(__file__).resolve().parent.parent / "build" / "wear_coverage"
    totals = {risk: [0, 0, 0] for risk in risks}  # planned, reached first, due after critical
    for seed in seeds:
        fleet = root / f"alt_seed_{seed}_5x120"
        truth = truth_dates(fleet / "depot" / "fleet_truth.json")
        with tempfile.TemporaryDirectory() as work:
            work = pathlib.Path(work)
            shutil.copy(fleet / "store.db", work / "store.db")
            store = f"sqlite:{work / 'store.db'}"
            subprocess.run([flange, "wear", "--store", store, "--out", str(work / "wear")],
                           check=True, capture_output=True)
            for risk in risks:
                for row in plan_rows(flange, store, work / f"plan_{risk}", risk):
                    true_date = truth[(row["locomotive"], int(row["axle"]), row["side"])]
                    total = totals[risk]
                    total[0] += 1
                    total[1] += bool(true_date) and true_date < row["due_date"]
                    critical = row["critical_date_at_rate"]
                    total[2] += critical[:1].isdigit() and row["due_date"] > critical
    for risk, (planned, first, late) in totals.items():
        print(f"risk {risk:g}: {planned} wheels planned, {first} reach the critical clearance "
              f"first ({100.0 * first / max(1, planned):.1f} %), {late} due after their "
              f"forecast critical date")


if __name__ == "__main__":
    main()
