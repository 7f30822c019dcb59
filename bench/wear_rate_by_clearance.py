# SPDX-License-Identifier: MIT
"""The rate's error and its 95 % interval's coverage by the clearance a wheel runs at, pooled over
fleets: a wear rate is the change of the stored clearance per km, so a calibration whose curve
reads a change of clearance short (or long) in some band of clearances moves the rates of the
wheels that run there, the same on every day, where no interval of the wear line sees it.
    python3 bench/wear_rate_by_clearance.py FLEET/wear/truth_check.json ...
Each wheel with a rate interval (the drifting sensors left out: their rate is the drift's as well)
goes into a band by the largest clearance of its runs; per band: the wheels, the median of
rate / true rate - 1 and the share of 95 % intervals that hold the true rate."""
import json
import os
import statistics
import sys

kBands = [(0.0, 4.5), (4.5, 6.5), (6.5, float("inf"))]


def band_name(low, high):
    if low == 0.0:
        return f"up to {high:g} mm"
    if high == float("inf"):
        return f"over {low:g} mm"
    return f"{low:g}-{high:g} mm"


def main(paths):
    rows = {band: [] for band in kBands}
    for path in paths:
        check = json.load(open(path))
        estimate = json.load(open(os.path.join(os.path.dirname(path), "wear.json")))
        by_wheel = {(w["locomotive"], w["axle"], w["side"]): w for w in estimate["wheels"]}
        for truth in check["wheels"]:
            wheel = by_wheel[(truth["locomotive"], truth["axle"], truth["side"])]
            if truth["kind"] == "drifting sensor" or not wheel.get("wear_rate_se"):
                continue
            largest = max(run["clearance_mm"] for run in wheel["runs"])
            band = next(b for b in kBands if b[0] < largest <= b[1])
            rows[band].append((wheel["wear_rate_mm_per_1000km"] / truth["true_rate"] - 1.0,
                               truth["rate_coverage"]["95"]))
    print("| largest clearance | wheels | rate error (median) | 95 % intervals that hold |")
    print("|---|---:|---:|---:|")
    for band, found in rows.items():
        if not found:
            continue
        error = 100.0 * statistics.median(e for e, _ in found)
        held = 100.0 * sum(1 for _, h in found if h) / len(found)
        print(f"| {band_name(*band)} | {len(found)} | {error:+.1f} % | {held:.1f} % |")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit("usage: wear_rate_by_clearance.py FLEET/wear/truth_check.json ...")
    main(sys.argv[1:])
