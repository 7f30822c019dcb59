# SPDX-License-Identifier: MIT
"""scipy.signal.sosfilt (float64) on the samples sample_model_bench used, beside its figures.

Run by bench/sosfilt_peer.sh, which runs sample_model_bench with --dump_dir=DIR first:
    python3 bench/sosfilt_peer.py DIR
DIR holds manifest.json, each set's input words and ReferenceFilter outputs, and bench.json
(Google Benchmark's JSON output). sosfilt gets the same words in full-scale units and the same
float SOS (filter.json's "sos", times its leftover gain); its output must equal ReferenceFilter's
to 1e-9 full scale, so both filter the same thing. Rates are samples per CPU second
(time.process_time), as Google Benchmark's items_per_second are.
"""
import json
import statistics
import sys
import time
from pathlib import Path

import numpy as np
import scipy
from scipy.signal import sosfilt

REPEATS = 7  # sosfilt calls per set; the median is reported
AIM = 2.0  # the sample model's throughput over sosfilt's
REFERENCE_AIM = 1.0  # ReferenceFilter::process's throughput over sosfilt's
SAME_FILTER_TOLERANCE = 1e-9  # full scale, sosfilt against ReferenceFilter


def bench_rates(path):
    """items_per_second per benchmark name: the median aggregate if repeated, else the run."""
    rates = {}
    for run in json.loads(Path(path).read_text())["benchmarks"]:
        name = run.get("run_name", run["name"])
        if run.get("run_type") == "aggregate":
            if run.get("aggregate_name") == "median":
                rates[name] = run["items_per_second"]
        elif name not in rates:
            rates[name] = run["items_per_second"]
    return rates


def sosfilt_rate(sos, x):
    sosfilt(sos, x[:1000])  # warm-up
    times = []
    for _ in range(REPEATS):
        start = time.process_time()
        y = sosfilt(sos, x)
        times.append(time.process_time() - start)
    return len(x) / statistics.median(times), y


def main():
    work = Path(sys.argv[1])
    rates = bench_rates(work / "bench.json")
    print(f"\nscipy {scipy.__version__}, numpy {np.__version__}: sosfilt float64, "
          f"median of {REPEATS} calls on the whole block")
    header = (f"{'set':<16} {'sample':>9} {'reference':>10} {'ref step':>9} {'IirCore':>9} "
              f"{'sosfilt':>9} {'sample/sosfilt':>15} {'aim >= 2':>9} {'ref/sosfilt':>12} "
              f"{'aim >= 1':>9} {'step/sosfilt':>13} {'max |diff|':>11}")
    print(header)
    failed = False
    for entry in json.loads((work / "manifest.json").read_text()):
        name = entry["name"]
        design = json.loads(Path(entry["filter_json"]).read_text())
        sos = np.array(design["sos"], dtype=np.float64)
        sos[:, :3] /= sos[:, 3:4]  # sosfilt wants a0 = 1; ReferenceFilter normalises the same way
        sos[:, 3:] /= sos[:, 3:4]
        sos[0, :3] *= design.get("leftover_gain", 1.0)
        full_scale = float(2 ** (entry["sample_width"] - 1))
        x = np.fromfile(entry["x"], dtype=np.int32).astype(np.float64) / full_scale
        reference = np.fromfile(entry["reference"], dtype=np.float64)
        rate, y = sosfilt_rate(sos, x)
        diff = float(np.max(np.abs(y - reference)))
        failed |= diff > SAME_FILTER_TOLERANCE
        sample = rates.get(f"SampleModel/{name}")
        ref = rates.get(f"ReferenceFilter/{name}")
        ref_step = rates.get(f"ReferenceFilterStep/{name}")
        core = rates.get(f"IirCore/{name}")
        ratio = sample / rate if sample else float("nan")
        ref_ratio = ref / rate if ref else float("nan")
        print(f"{name:<16} {sample / 1e6:>8.2f}M {ref / 1e6:>9.2f}M {ref_step / 1e6:>8.2f}M "
              f"{core / 1e6:>8.2f}M {rate / 1e6:>8.2f}M {ratio:>15.2f} "
              f"{'met' if ratio >= AIM else 'NOT met':>9} {ref_ratio:>12.2f} "
              f"{'met' if ref_ratio >= REFERENCE_AIM else 'NOT met':>9} "
              f"{ref_step / rate:>13.2f} {diff:>11.2e}")
    if failed:
        print(f"sosfilt_peer: sosfilt and ReferenceFilter differ by more than "
              f"{SAME_FILTER_TOLERANCE:g}: not the same filter", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
