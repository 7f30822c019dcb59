#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Independent, standard-library-only re-implementation of the fixed-point contract
# (docs/fixed_point.md) next to two variants, for the comparison in docs/core.md:
#   contract: extended-precision feedback. Each section keeps its own output history y_ext with
#             s = FeedbackShift more fractional bits than a sample (D + s <= 25 bits, the DSP48E1
#             A port): y_ext = sat_(D+s)((acc + 2^(Fa-1)) >>> Fa). The section's D-bit output (the
#             next section's input, the filter output) is rounded again from y_ext:
#             y = sat_D((y_ext + 2^(s-1)) >>> s) (double rounding).
#   direct:   the same history, but y rounded directly from the accumulator,
#             y = sat_D((acc + 2^(Fb-1)) >>> Fb) (what double rounding saves a second adder on).
#   narrow:   the contract before extended precision: every section's output is rounded to D bits
#             and that D-bit value, shifted left by s, is the feedback history.
# For each filter.json: SNR and largest error against the float SOS for a passband sine (fc / 4)
# at 0.5 and 0.05 of full scale, and the zero-input tail after a half-scale negative step.
#   python3 scripts/fixed_point_variants.py coeffs/vehicle_sos/filter.json [...]
# The "contract" rows must equal the C++ model (tests/model/iir_core_fidelity_test.cpp prints the
# same SNR figures, and IirCoreModel.* checks hand-computed cases of the same arithmetic).
import json
import math
import sys

VARIANTS = ("contract", "direct", "narrow")


def load(path):
    with open(path, encoding="utf-8") as f:
        d = json.load(f)
    return d, d["quantized"]


def clamp(v, lo, hi):
    return max(lo, min(hi, v))


def run(q, xs, variant):
    w = q["words"]
    fb = q["b_frac_bits"]
    fa = q["coef_frac_bits"]
    s = q["feedback_shift"]
    k_sections = q["sections"]
    m = q["section_order"]
    terms = 2 * m + 1
    d_bits = q["data_bits"]
    lo, hi = -(2 ** (d_bits - 1)), 2 ** (d_bits - 1) - 1
    ext_lo, ext_hi = lo * 2**s, (hi + 1) * 2**s - 1
    half_s = 2 ** (s - 1) if s > 0 else 0
    xh = [[0] * (m + 1) for _ in range(k_sections)]  # D-bit inputs per section, newest first
    yh = [[0] * (m + 1) for _ in range(k_sections)]  # feedback operand per section (D + s bits)
    out = []
    for x in xs:
        v = x
        for k in range(k_sections):
            xh[k].insert(0, xh[k].pop())
            xh[k][0] = v
            yh[k].insert(0, yh[k].pop())
            raw = sum(w[k * terms + i] * xh[k][i] for i in range(m + 1))
            raw += sum(w[k * terms + m + j] * yh[k][j] for j in range(1, m + 1))
            if variant == "narrow":
                y = clamp((raw + 2 ** (fb - 1)) >> fb, lo, hi)
                yh[k][0] = y * 2**s
            else:
                y_ext = clamp((raw + 2 ** (fa - 1)) >> fa, ext_lo, ext_hi)
                yh[k][0] = y_ext
                if variant == "contract":
                    y = clamp((y_ext + half_s) >> s, lo, hi)
                else:
                    y = clamp((raw + 2 ** (fb - 1)) >> fb, lo, hi)
            v = y
        out.append(v)
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
