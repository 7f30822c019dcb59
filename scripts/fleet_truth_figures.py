#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The figures of `flange wear --truth` by wheel kind: for a truth file that names each wheel's
kind (flange simulate --scenario fleet-alt writes "healthy", "reprofiled", "sensor replaced",
"wheelset moved" or "drifting sensor"; a wheel without one counts as "all"), the wheels, the
rates within 10 % of the truth, the median and largest relative error, how often the 95 %
interval holds the true rate, and the flags. Usage:
  fleet_truth_figures.py fleet_truth.json wear/truth_check.json"""
import json
import statistics
import sys


def kinds(truth):
    by_wheel = {}
    for loco in truth["locomotives"]:
        for wheel in loco["wheels"]:
            by_wheel[(loco["name"], wheel["axle"], wheel["side"])] = wheel.get("kind", "all")
    return by_wheel


def row(name, wheels):
    errors = [abs(w["relative_error"]) for w in wheels]
    inside = sum(1 for w in wheels if w["rate_low"] <= w["true_rate"] <= w["rate_high"])
    within = sum(1 for e in errors if e <= 0.10)
    flagged = sum(1 for w in wheels if w["flagged"])
    return (f"| {name} | {len(wheels)} | {within} | {100 * statistics.median(errors):.1f} % | "
            f"{100 * max(errors):.1f} % | {inside} of {len(wheels)} "
            f"({100 * inside / len(wheels):.0f} %) | {flagged} |")


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    with open(sys.argv[1]) as f:
        truth = json.load(f)
    with open(sys.argv[2]) as f:
        check = json.load(f)
    kind_of = kinds(truth)
    groups = {}
    for wheel in check["wheels"]:
        kind = kind_of.get((wheel["locomotive"], wheel["axle"], wheel["side"]), "all")
        groups.setdefault(kind, []).append(wheel)
    print("| wheels | n | rate within 10 % | median error | largest error | "
          "truth inside the 95 % interval | flagged as sensor fault |")
    print("|---|---|---|---|---|---|---|")
    for kind in sorted(groups):
        print(row(kind, groups[kind]))
    print(row("all", check["wheels"]))
    print(f"\nreprofilings found: {check['reprofilings_found']} of {check['reprofilings']}; "
          f"drifting sensors flagged: {check['drifting_flagged']} of {check['drifting']}; "
          f"healthy sensors flagged: {check['healthy_flagged']}")


if __name__ == "__main__":
    main()
