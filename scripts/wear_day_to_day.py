# SPDX-License-Identifier: MIT
"""How much each wheel's stored clearance moves from one run to the next beyond its wear: for every
wheel of a `flange wear` output (wear.json), the change between successive runs of one flange
(same segment) less the wheel's median change, pooled; prints the median absolute deviation of
those changes for the wheels, and the standard deviation of the axle's sum and difference
changes (per run: divided by sqrt 2), with the correlation of left and right.
    python3 scripts/wear_day_to_day.py OUT/wear.json"""
import json
import math
import statistics
import sys

wheels = {(w["locomotive"], w["axle"], w["side"]): w for w in json.load(open(sys.argv[1]))["wheels"]}


def changes(runs_a, runs_b):
    """Successive changes of two wheels over the runs both have, each less its median."""
    a_at, b_at = {r["at"]: r for r in runs_a}, {r["at"]: r for r in runs_b}
    common = sorted(set(a_at) & set(b_at))
    da, db = [], []
    for p, q in zip(common, common[1:]):
        if a_at[p]["segment"] != a_at[q]["segment"] or b_at[p]["segment"] != b_at[q]["segment"]:
            continue
        da.append(a_at[q]["clearance_mm"] - a_at[p]["clearance_mm"])
        db.append(b_at[q]["clearance_mm"] - b_at[p]["clearance_mm"])
    if len(da) < 5:
        return [], []
    ma, mb = statistics.median(da), statistics.median(db)
    return [v - ma for v in da], [v - mb for v in db]


left, right = [], []
for (loco, axle, side), wheel in wheels.items():
    partner = wheels.get((loco, axle, "right"))
    if side == "left" and partner:
        dl, dr = changes(wheel["runs"], partner["runs"])
        left += dl
        right += dr
both = left + right
mad = statistics.median(abs(v) for v in both)
rms = lambda v: math.sqrt(sum(x * x for x in v) / len(v) / 2.0)
corr = sum(x * y for x, y in zip(left, right)) / math.sqrt(
    sum(x * x for x in left) * sum(y * y for y in right))
print(f"{len(both)} changes: wheel MAD {mad:.4f} mm; per run sd: wheel {rms(both):.4f}, "
      f"sum {rms([x + y for x, y in zip(left, right)]):.4f}, difference "
      f"{rms([y - x for x, y in zip(left, right)]):.4f} mm; left-right correlation {corr:.2f}")
