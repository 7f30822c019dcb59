#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Independent, standard-library-only re-implementation of the fixed-point contract
# (docs/fixed_point.md, contract v2) next to two variants that each drop one of its parts, for the
# comparison in docs/core.md:
#   contract:  split coefficients (hi + lo words, F + L fractional bits), the lo phase shifted by
#              L, every signal between sections in D + s bits, error feedback through E.
#   no_error:  the same without error feedback (E = 0): the rounding noise passes 1/A(z).
#   one_word:  no lo words (each coefficient rounded to its hi word's F fractional bits), with
#              error feedback: what the 18-bit words alone allow.
# For each filter.json: SNR and largest error against the float SOS for a passband sine (fc / 4)
# at 0.5 and 0.05 of full scale, and the zero-input tail after a half-scale negative step.
#   python3 scripts/fixed_point_variants.py coeffs/vehicle_sos/filter.json [...]
# The "contract" rows must equal the C++ model (IirCoreModel.* checks hand-computed cases of the
# same arithmetic; tests/coeffs/precision_grid_test.cpp and bench/core_bench measure the SNR).
import json
import math
import sys

VARIANTS = ("contract", "no_error", "one_word")


def load(path):
    with open(path, encoding="utf-8") as f:
        d = json.load(f)
    return d, d["quantized"]


def clamp(v, lo, hi):
    return max(lo, min(hi, v))


def run(q, xs, variant):
    w = q["words"]
    f = q["coef_frac_bits"]
    s = q["feedback_shift"]
    split = q["split_shift"]
    k_sections = q["sections"]
    m = q["section_order"]
    terms = 5 * m + 2
    d_bits = q["data_bits"]
    lo, hi = -(2 ** (d_bits - 1)), 2 ** (d_bits - 1) - 1
    ext_lo, ext_hi = lo * 2**s, (hi + 1) * 2**s - 1
    half_s = 2 ** (s - 1) if s > 0 else 0
    uh = [[0] * (m + 1) for _ in range(k_sections)]  # section inputs, D + s bits, newest first
    yh = [[0] * (m + 1) for _ in range(k_sections)]  # section outputs y_ext
    eh = [[0] * (m + 1) for _ in range(k_sections)]  # rounding errors
    out = []
    for x in xs:
        v = x * 2**s
        for k in range(k_sections):
            base = k * terms
            lo_b = w[base : base + m + 1]
            lo_a = [0] + w[base + m + 1 : base + 2 * m + 1]
            hi_b = w[base + 2 * m + 1 : base + 3 * m + 2]
            hi_a = [0] + w[base + 3 * m + 2 : base + 4 * m + 2]
            err = [0] + w[base + 4 * m + 2 : base + 5 * m + 2]
            if variant == "no_error":
                err = [0] * (m + 1)
            if variant == "one_word":
                # Each coefficient rounded half away from zero to F fractional bits.
                def one(h, l):
                    c = h * 2**split + l
                    r = (abs(c) + 2 ** (split - 1)) >> split
                    return r if c >= 0 else -r
                hi_b = [one(h, l) for h, l in zip(hi_b, lo_b)]
                hi_a = [one(h, l) for h, l in zip(hi_a, lo_a)]
                lo_b, lo_a = [0] * (m + 1), [0] * (m + 1)
            for hist in (uh[k], yh[k], eh[k]):
                hist.insert(0, hist.pop())
            uh[k][0] = v
            acc_lo = 2 ** (f - 1 + split)
            acc_lo += sum(lo_b[i] * uh[k][i] for i in range(m + 1))
            acc_lo += sum(lo_a[j] * yh[k][j] for j in range(1, m + 1))
            acc = acc_lo >> split
            acc += sum(hi_b[i] * uh[k][i] for i in range(m + 1))
            acc += sum(hi_a[j] * yh[k][j] + err[j] * eh[k][j] for j in range(1, m + 1))
            y_ext = clamp(acc >> f, ext_lo, ext_hi)
            yh[k][0] = y_ext
            eh[k][0] = (acc % 2**f) - 2 ** (f - 1)
            v = y_ext
        out.append(clamp((v + half_s) >> s, lo, hi))
    return out


def sosfilt(sos, xs):
    st = [[0.0] * 4 for _ in sos]
    out = []
    for x in xs:
        v = x
        for k, (b0, b1, b2, _a0, a1, a2) in enumerate(sos):
            x1, x2, y1, y2 = st[k]
            y = b0 * v + b1 * x1 + b2 * x2 - a1 * y1 - a2 * y2
            st[k] = [v, x1, y, y1]
            v = y
        out.append(v)
    return out


def main(paths):
    for p in paths:
        d, q = load(p)
        name = p.split("/")[-2]
        fs, fc = d["fs_hz"], d["fc_hz"]
        scale = 2 ** (q["data_bits"] - 1)
        n, skip = 40000, 15000
        for level in (0.5, 0.05):
            x = [round(level * math.sin(2 * math.pi * fc / 4 * i / fs) * scale) for i in range(n)]
            ref = [v * scale for v in sosfilt(d["sos"], [v / scale for v in x])]
            for variant in VARIANTS:
                y = run(q, x, variant)
                e = [a - b for a, b in zip(y[skip:], ref[skip:])]
                snr = 10 * math.log10(sum(r * r for r in ref[skip:]) / sum(v * v for v in e))
                print(f"{name:16s} level {level:4.2f} {variant:8s}: SNR {snr:6.1f} dB, "
                      f"max err {max(abs(v) for v in e):8.1f} LSB")
        for variant in VARIANTS:
            y = run(q, [-16384] * 4000 + [0] * 30000, variant)
            print(f"{name:16s} zero-input tail {variant:8s}: min {min(y[-3000:])} "
                  f"max {max(y[-3000:])}")


if __name__ == "__main__":
    main(sys.argv[1:])
