#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""bench/wear_coverage_table.py brackets each share over whole locomotives and over whole fleets:
two made-up fleets of four locomotives, every healthy wheel's warning date held in the first and
missed in the second. Over the eight locomotives the share's range stays well inside 0-100 %;
over the two fleets half the draws are one fleet twice, so the range is all of 0-100 %."""
import json
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(sys.argv[1])


def held(value):
    return {"95": value, "80": value}


def forecast():
    return {"reached": False, "days": 100.0, "days_low": 80.0, "days_high": 120.0,
            "date_low": "2028-01-01"}


def fleet(holds):
    checked, estimated = [], []
    for loco in ("A01", "A02", "A03", "A04"):
        for axle in (1, 2):
            checked.append({"locomotive": loco, "axle": axle, "side": "left", "kind": "healthy",
                            "true_rate": 0.05, "relative_error": 0.01,
                            "rate_coverage": held(True), "warning_coverage": held(holds),
                            "critical_coverage": held(True), "true_warning_date": "2028-03-01",
                            "true_critical_date": "2028-06-01"})
            estimated.append({"locomotive": loco, "axle": axle, "side": "left",
                              "wear_rate_mm_per_1000km": 0.05, "wear_rate_low": 0.045,
                              "wear_rate_high": 0.055, "wear_rate_se": 0.0025, "interval_dof": 9,
                              "warning": forecast(), "critical": forecast(),
                              "runs": [{"at": "2027-07-01T08:00:00.000Z"}]})
    check = {"wheels": checked, "rates_ok": len(checked), "reprofilings_found": 0,
             "reprofilings": 0, "drifting_flagged": 0, "drifting": 0, "healthy_flagged": 0,
             "passed": holds}
    return check, {"wheels": estimated}


with tempfile.TemporaryDirectory() as tmp:
    paths = []
    for name, holds in (("held", True), ("missed", False)):
        folder = Path(tmp) / name / "wear"
        folder.mkdir(parents=True)
        check, estimate = fleet(holds)
        (folder / "truth_check.json").write_text(json.dumps(check))
        (folder / "wear.json").write_text(json.dumps(estimate))
        paths.append(str(folder / "truth_check.json"))
    out = subprocess.run([sys.executable, str(ROOT / "bench/wear_coverage_table.py"), *paths],
                         check=True, capture_output=True, text=True).stdout

lines = out.splitlines()
by_locomotive = [l for l in lines if l.startswith("| healthy | warning date | 16 |")]
by_fleet = [l for l in lines if l.startswith("| healthy | warning date | [")]
problems = []
if len(by_locomotive) != 1 or "| 8 (50.0 %) [" not in by_locomotive[0]:
    problems.append("the counts row: 8 of 16 held, with a range over locomotives")
else:
    low = float(by_locomotive[0].split("| 8 (50.0 %) [")[1].split(",")[0])
    if not 0.0 < low < 50.0:
        problems.append(f"the locomotives' range starts at {low}, not inside 0-50 %")
if by_fleet != ["| healthy | warning date | [0.0, 100.0] | [0.0, 100.0] |"]:
    problems.append("the fleets' range of the healthy warning date: [0.0, 100.0] at both levels")
if "draws of the 2 fleets, resampled whole" not in out:
    problems.append("the fleets' table heading")
if problems:
    sys.exit("wear_coverage_table_test: " + "; ".join(problems) + "\n--- got:\n" + out)
