#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""What it would take for every Butterworth SOS set to reach ~89 dB at fc/4 (issue 12), as a
design study, not a test: /usr/bin/python3 bench/precision_study.py (needs python3-scipy,
`bash scripts/setup.sh --bench`). Figures in docs/benchmarks_core.md#what-would-close-the-gap.

Two independent estimates, both against the float design of scipy.signal.butter:
1. Coefficient rounding alone: -20 log10 |H_q - H| / |H| at fc/4 for a cascade of unity-DC
   biquads whose denominators are rounded (a) in direct form into one C-bit format, as the core
   does today, and (b) in an "offset" form: -a_j = c_j + r_j with c_j the nearest integer (exact,
   added outside the multiplier) and only the small r_j rounded, into a format fitted to the
   largest |r|. The numerator is rescaled for unity DC after the denominator is rounded, as the
   generator does.
2. Arithmetic alone: the white-noise model of floor B with the feedback history s bits finer than
   a sample: each section's y_ext rounding (LSB 2^-(D-1+s)) through 1/A_k and the later sections,
   plus one output rounding.
"""
import numpy as np
from scipy import signal

D = 16
RATIOS = [0.001, 0.0026, 0.01, 0.05, 0.1, 0.2, 0.4]
ORDERS = [1, 2, 4, 7, 8, 12]


def frac_bits(values, c):
    largest = max(np.abs(np.asarray(values)).max(), 1e-30)
    f = c - 1 - int(np.ceil(np.log2(largest)))
    if np.abs(np.round(np.asarray(values) * 2.0**f)).max() > 2 ** (c - 1) - 1:
        f -= 1
    return f


def rounded(values, f):
    return np.round(np.asarray(values) * 2.0**f) / 2.0**f


def unity_dc(sos):
    out = sos.copy()
    for row in out:
        row[:3] *= np.sum(row[3:]) / np.sum(row[:3])
    return out


def quantised(sos, c, offset):
    neg_a = [-row[4:6] for row in sos]
    whole = [np.round(r) if offset else np.zeros(2) for r in neg_a]
    small = [r - w for r, w in zip(neg_a, whole)]
    f = frac_bits(np.concatenate(small), c)
    out = []
    for row, w, r in zip(sos, whole, small):
        a = np.array([1.0, *(-(rounded(r, f) + w))])
        b = np.asarray(row[:3]) / np.sum(row[:3]) * np.sum(a)
        out.append([*rounded(b, min(frac_bits(b, c), f + 9)), *a])
    return np.array(out)


def response(sos, w):
    z = np.exp(1j * w)
    h = 1.0
    for row in sos:
        h *= (row[0] + row[1] / z + row[2] / z**2) / (row[3] + row[4] / z + row[5] / z**2)
    return h


def coefficient_snr(order, ratio, c, offset):
    sos = unity_dc(signal.butter(order, 2 * ratio, output="sos"))
    w = 2 * np.pi * ratio / 4
    h = response(sos, w)
    return -20 * np.log10(abs(response(quantised(sos, c, offset), w) - h) / abs(h) + 1e-30)


def arithmetic_snr(order, ratio, s):
    sos = unity_dc(signal.butter(order, 2 * ratio, output="sos"))
    n = int(60 / ratio)
    gain = 0.0
    for k in range(len(sos)):
        impulse = np.zeros(n)
        impulse[0] = 1.0
        h = signal.lfilter([1.0], sos[k][3:], impulse)
        if k + 1 < len(sos):
            h = signal.sosfilt(sos[k + 1 :], h)
        gain += np.sum(h * h)
    noise = (2.0 ** -(D - 1 + s)) ** 2 / 12 * gain + (2.0 ** -(D - 1)) ** 2 / 12
    return 10 * np.log10(0.5 * 10**-0.1 / noise)


def table(title, figure):
    print(f"\n{title}\n")
    print("| order | " + " | ".join(f"fc/fs {r:g}" for r in RATIOS) + " |")
    print("|---|" + "---|" * len(RATIOS))
    for order in ORDERS:
        print(f"| {order} | " + " | ".join(f"{figure(order, r):.1f}" for r in RATIOS) + " |")


table("Coefficient SNR (dB), direct form, 18-bit words (the core today)",
      lambda n, r: coefficient_snr(n, r, 18, False))
table("Coefficient SNR (dB), offset form, 18-bit words", lambda n, r: coefficient_snr(n, r, 18, True))
table("Coefficient SNR (dB), direct form, 25-bit words", lambda n, r: coefficient_snr(n, r, 25, False))
table("Coefficient SNR (dB), offset form, 25-bit words", lambda n, r: coefficient_snr(n, r, 25, True))
table("Arithmetic SNR (dB), history s = 7 bits finer (vehicle_sos today)",
      lambda n, r: arithmetic_snr(n, r, 7))
table("Arithmetic SNR (dB), s = 9 (D + s = 25, the A port's limit)",
      lambda n, r: arithmetic_snr(n, r, 9))
