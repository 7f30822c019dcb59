# SPDX-License-Identifier: MIT
"""Whether the fleet's bend b and calendar trend gamma (host/wear/wear_acceleration.h) scatter
from fleet to fleet of one reality as their standard errors say: each wear.json's
`fleet_acceleration`, then over the fleets the mean, the standard deviation, the median standard
error and their ratio. Fleets of one reality share its law (the second reality's b is 0.06 per mm;
its gamma moves only with each draw's weather), so the spread over fleets is the estimates' own
error and a ratio well over 1 is an error the standard errors do not hold. With --true-per-mm
the estimates' z = (b - true) / se too.
    python3 bench/fleet_acceleration_scatter.py [--true-per-mm B] FLEET/wear/wear.json ..."""
import json
import statistics
import sys

args = sys.argv[1:]
true_b = None
if args[:1] == ["--true-per-mm"]:
    true_b, args = float(args[1]), args[2:]
rows = []
for path in args:
    bend = json.load(open(path)).get("fleet_acceleration")
    if bend is None:
        print(f"{path}: no fleet acceleration estimated")
        continue
    rows.append(bend)
    print(f"{path}: b {bend['per_mm']:+.4f} (se {bend['per_mm_se']:.4f}, in dates "
          f"{bend['per_mm_in_dates']:.4f}), gamma {bend['trend_per_day']:+.5f} per day "
          f"(se {bend['trend_per_day_se']:.5f}), {bend['dof']} dof")
if len(rows) < 2:
    sys.exit("need two fleets or more")
terms = (("b", "per_mm", "per_mm_se"), ("gamma", "trend_per_day", "trend_per_day_se"))
for name, value, se in terms:
    values = [r[value] for r in rows]
    spread = statistics.stdev(values)
    typical = statistics.median(r[se] for r in rows)
    print(f"{name}: mean {statistics.mean(values):+.5f} over {len(rows)} fleets, sd {spread:.5f}, "
          f"median se {typical:.5f}, sd / median se {spread / typical:.2f}")
if true_b is not None:
    z = [(r["per_mm"] - true_b) / r["per_mm_se"] for r in rows]
    print(f"b against {true_b}: z mean {statistics.mean(z):+.2f}, sd {statistics.stdev(z):.2f}, "
          f"|z| > 2 on {sum(abs(v) > 2 for v in z)} of {len(z)}")
