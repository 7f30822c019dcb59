#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# The reprofiling plan (docs/fleet.md, "Reprofiling plan") against the fleets' true critical
# dates: for each seed's fleet in build/wear_coverage/ (alt_seed_S_5x120/ with store.db and
# depot/fleet_truth.json, as bench/wear_coverage_alt.sh leaves the second reality's, or
# seed_S_5x90/ with fleet.db and fleet_truth.json, as bench/wear_coverage.sh leaves the
# first's), a copy of its store is estimated by `flange wear --truth` (which keeps the estimates
# and writes each wheel's true critical date into truth_check.json), then planned from the kept
# estimates at each risk with a horizon past every date. A wheel reaches the critical clearance
# first when its true critical date is before its due date. Prints, per risk, the wheels
# planned, how many reach it first (the share should be the risk) and how many are due after
# their own forecast critical date.
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


def fleet_files(root, seed):
    """The seed's store and truth file, on either reality."""
    second = root / f"alt_seed_{seed}_5x120"
    if second.is_dir():
        return second / "store.db", second / "depot" / "fleet_truth.json"
    first = root / f"seed_{seed}_5x90"
    return first / "fleet.db", first / "fleet_truth.json"


def estimate_with_truth(flange, store, truth, out):
    """`flange wear --truth` (exit 1: a failed check, still written); the true critical dates."""
    done = subprocess.run([flange, "wear", "--store", store, "--out", str(out), "--truth",
                           str(truth)], capture_output=True, text=True)
    if done.returncode > 1:
        sys.exit(f"{store}: flange wear failed ({done.returncode}):\n{done.stderr}")
    check = json.loads((out / "truth_check.json").read_text())
    return {(w["locomotive"], int(w["axle"]), w["side"]): w.get("true_critical_date", "")
            for w in check["wheels"]}


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
        store_file, truth_file = fleet_files(root, seed)
        with tempfile.TemporaryDirectory() as work:
            work = pathlib.Path(work)
            shutil.copy(store_file, work / "store.db")
            store = f"sqlite:{work / 'store.db'}"
            truth = estimate_with_truth(flange, store, truth_file, work / "wear")
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
