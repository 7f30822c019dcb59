# SPDX-License-Identifier: MIT
"""How often `flange wear`'s intervals hold the truth, pooled over fleets: the per-wheel checks of
each fleet's truth_check.json (with its wear.json beside it) in one table by wheel kind, for the
rate and the dates of the warning and critical limits at 95 % and 80 %; then the rate,
reprofiling and drift checks summed over the fleets, the 95 % intervals' widths and which way
the dates' intervals miss (true days over forecast days, misses before and after).
    python3 bench/wear_coverage_table.py FLEET/wear/truth_check.json ...
Each share comes with a 90 % range from a bootstrap over locomotives: the wheels of a locomotive
share its km per day (the dates) and its route, season and sensors' installation (the rate), so
their checks are not independent draws. The locomotives of all fleets are resampled whole, with
replacement, kBootstrapDraws times (from a fixed seed), and the 5th and 95th percentiles of the
share that holds are printed in brackets: a share whose range covers the level is within what the
locomotives' own scatter gives. The wheels of a fleet also share what is pooled over it (the
fleet's bend and calendar trend, its calibration, its weather), so a second table gives the same
ranges with the fleets resampled whole: the wider of the two is the honest one when the misses
come a fleet at a time.
Used by bench/wear_coverage.sh and bench/wear_coverage_alt.sh."""
import datetime
import json
import math
import os
import random
import statistics
import sys

kBootstrapDraws = 2000

checks = [json.load(open(path)) for path in sys.argv[1:]]
estimates = [json.load(open(os.path.join(os.path.dirname(path), "wear.json")))
             for path in sys.argv[1:]]
wheels = [w for c in checks for w in c["wheels"]]
# The fleet scenario's kinds first, then any other reality's in the order met.
kinds = ["healthy", "reprofiled", "drifting sensor"]
kinds += [k for k in dict.fromkeys(w["kind"] for w in wheels) if k not in kinds] + ["all"]
quantities = [("rate", "rate_coverage"), ("warning date", "warning_coverage"),
              ("critical date", "critical_coverage")]
# The checks of each locomotive (fleet index, name), for the bootstrap.
locomotives = {}
for f, check in enumerate(checks):
    for w in check["wheels"]:
        locomotives.setdefault((f, w["locomotive"]), []).append(w)
clusters = list(locomotives.values())
fleets = [check["wheels"] for check in checks]
cells = [(kind, name, field) for kind in kinds for name, field in quantities]


def cell_counts(wheel_list, kind, field):
    """(checked, held at 95 %, held at 80 %) among `wheel_list`."""
    known = [w[field] for w in wheel_list
             if (kind == "all" or w["kind"] == kind) and w[field] is not None]
    return (len(known), sum(1 for c in known if c["95"]), sum(1 for c in known if c["80"]))


def bootstrap_shares(groups):
    """Per cell, the share that holds at 95 % and at 80 % over each draw of `groups` (lists of
    wheel checks) resampled whole with replacement."""
    per_group = {cell: [cell_counts(g, cell[0], cell[2]) for g in groups] for cell in cells}
    draws = random.Random(20470).choices
    shares = {cell: ([], []) for cell in cells}
    for _ in range(kBootstrapDraws):
        chosen = draws(range(len(groups)), k=len(groups))
        for cell in cells:
            counts = per_group[cell]
            checked = sum(counts[i][0] for i in chosen)
            if checked == 0:
                continue
            for level in (0, 1):
                shares[cell][level].append(sum(counts[i][1 + level] for i in chosen) / checked)
    return shares


shares = bootstrap_shares(clusters)


def share_range(values):
    if not values:
        return ""
    values = sorted(values)
    low, high = values[int(0.05 * len(values))], values[int(0.95 * len(values)) - 1]
    return f" [{100.0 * low:.1f}, {100.0 * high:.1f}]"


print(f"\n{len(checks)} fleets, {len(clusters)} locomotives, {len(wheels)} wheels\n")
print("| wheels | interval of | checked | holds the truth at 95 % | at 80 % |")
print("|---|---|---|---|---|")
for cell in cells:
    kind, name, field = cell
    checked, held95, held80 = cell_counts(wheels, kind, field)
    if not checked:
        print(f"| {kind} | {name} | 0 | - | - |")
        continue
    text = [f"{held} ({100.0 * held / checked:.1f} %){share_range(shares[cell][level])}"
            for level, held in enumerate((held95, held80))]
    print(f"| {kind} | {name} | {checked} | {text[0]} | {text[1]} |")
print(f"\n[low, high]: the 5th and 95th percentiles of the share over {kBootstrapDraws} draws of "
      f"the {len(clusters)} locomotives, resampled whole")
if len(fleets) >= 2:
    fleet_shares = bootstrap_shares(fleets)
    print(f"\nThe same ranges over {kBootstrapDraws} draws of the {len(fleets)} fleets, resampled "
          f"whole:\n")
    print("| wheels | interval of | at 95 % | at 80 % |")
    print("|---|---|---|---|")
    for cell in cells:
        if cell_counts(wheels, cell[0], cell[2])[0]:
            print(f"| {cell[0]} | {cell[1]} |{share_range(fleet_shares[cell][0])} |"
                  f"{share_range(fleet_shares[cell][1])} |")
total = lambda key: sum(c[key] for c in checks)
errors = [abs(w["relative_error"]) for w in wheels if w["relative_error"] is not None]
print(f"\nrates within 10 % or inside the interval: {total('rates_ok')} of {len(wheels)} "
      f"(largest error {100.0 * max(errors):.1f} %, median {100.0 * statistics.median(errors):.1f} "
      f"%); reprofilings found: {total('reprofilings_found')} of {total('reprofilings')}; "
      f"drifting sensors flagged: {total('drifting_flagged')} of {total('drifting')}; healthy "
      f"sensors flagged: {total('healthy_flagged')}; fleets passing: "
      f"{sum(c['passed'] for c in checks)} of {len(checks)}")
# How wide the 95 % intervals are: half the rate's in % of the rate, half the warning date's in days.
rate_widths, date_widths = [], []
for estimate in estimates:
    for w in estimate["wheels"]:
        rate = w["wear_rate_mm_per_1000km"]
        if rate is None or rate <= 0.0 or w["wear_rate_high"] is None:
            continue
        rate_widths.append(50.0 * (w["wear_rate_high"] - w["wear_rate_low"]) / rate)
        warning = w["warning"]
        if warning and not warning["reached"] and warning["days_low"] is not None \
                and warning["days_high"] is not None:
            date_widths.append((warning["days_high"] - warning["days_low"]) / 2.0)
if rate_widths:
    print(f"95 % intervals: rate +- {statistics.median(rate_widths):.2f} % (median of "
          f"{len(rate_widths)} positive rates; 90th percentile "
          f"{sorted(rate_widths)[int(0.9 * len(rate_widths))]:.2f} %)" +
          (f", warning date +- {statistics.median(date_widths):.1f} days (median of "
           f"{len(date_widths)})" if date_widths else ""))
# Which way a date's 95 % interval misses, and how far the truth lies from the forecast: per limit,
# the wheels whose true date is before the interval and after it (a true date past the truth's
# horizon counts as after), and the median of the true days to the limit over the forecast's
# (from the last run's day to the middle of the true date's day).
def day_number(text):
    return (datetime.date.fromisoformat(text[:10]) - datetime.date(1970, 1, 1)).days


def run_day(at):
    stamp = datetime.datetime.fromisoformat(at.replace("Z", "+00:00"))
    return stamp.timestamp() / 86400.0


for limit in ("warning", "critical"):
    early, late, ratios = 0, 0, []
    for check, estimate in zip(checks, estimates):
        estimated = {(w["locomotive"], w["axle"], w["side"]): w for w in estimate["wheels"]}
        for truth in check["wheels"]:
            held = truth[limit + "_coverage"]
            if held is None:
                continue
            w = estimated[(truth["locomotive"], truth["axle"], truth["side"])]
            forecast, true_date = w[limit], truth["true_" + limit + "_date"]
            last = math.floor(run_day(w["runs"][-1]["at"]))
            if true_date and forecast["days"] and not forecast["reached"]:
                ratios.append((day_number(true_date) - last + 0.5) / forecast["days"])
            if held["95"]:
                continue
            low = forecast["date_low"]
            if true_date and low and not low.startswith("after") and \
                    day_number(true_date) < day_number(low):
                early += 1
            else:
                late += 1
    if ratios:
        print(f"{limit} date: true over forecast days {statistics.median(ratios):.3f} (median of "
              f"{len(ratios)}); 95 % misses: {early} before the interval, {late} after it")
# Why an interval holds more or less often than it says: each wheel's rate error over its
# standard error, |T| = |rate - truth| / se, against the Student t the interval takes it for (its
# quantiles in closed form at 2 degrees of freedom, which every history of up to about 20 weeks
# has: q = (2p - 1) / sqrt(2 p (1 - p)) at p = (1 + level) / 2).
by_dof = {}
for check, estimate in zip(checks, estimates):
    estimated = {(w["locomotive"], w["axle"], w["side"]): w for w in estimate["wheels"]}
    for truth in check["wheels"]:
        w = estimated[(truth["locomotive"], truth["axle"], truth["side"])]
        if w["wear_rate_se"] and w["wear_rate_mm_per_1000km"] is not None:
            error = abs(w["wear_rate_mm_per_1000km"] - truth["true_rate"]) / w["wear_rate_se"]
            by_dof.setdefault(w["interval_dof"], []).append(error)
levels = (0.5, 0.8, 0.9, 0.95)
for dof, errors in sorted(by_dof.items()):
    errors.sort()
    found = " ".join(f"{errors[min(len(errors) - 1, int(level * len(errors)))]:.2f}"
                     for level in levels)
    line = f"|T| at {dof} degrees of freedom ({len(errors)} wheels), quantiles 50/80/90/95 %: {found}"
    if dof == 2:
        t2 = lambda p: (2 * p - 1) / (2 * p * (1 - p)) ** 0.5
        line += " (Student t: " + " ".join(f"{t2((1 + level) / 2):.2f}" for level in levels) + ")"
    print(line)
