# SPDX-License-Identifier: MIT
"""How a depot's calibration reads a change of clearance on the second fleet reality: the slope of
the calibrated clearance against the true one, d(d_cal)/dd, for the reality's nominal sensor unit
(gain 1, no zero or voltage offset) at three coil temperatures. A slope under 1 reads wear short,
so the rate of a wheel that runs at those clearances comes out low by as much, every day alike.
    python3 bench/calibration_slope_alt.py FLEET/wear/calibration.json ...
The law is sim/fleet_alt/fleet_alt_sensor.h's, written out here as a peer:
    V = Vsat (1 - k_s (T - 20)) (1 - exp(-d / (lambda (1 + k_l (T - 20)))))"""
import json
import math
import sys

kVsat, kLambdaMm, kScalePerC, kLengthPerC = 13.0, 9.0, 0.0016, 0.0009
kTemperaturesC = (15.0, 30.0, 45.0)
kClearancesMm = (2.5, 3.5, 4.5, 5.5, 6.5, 7.5, 8.5)
kStepMm = 0.25


def nominal_voltage(clearance_mm, temp_c):
    length = kLambdaMm * (1.0 + kLengthPerC * (temp_c - 20.0))
    return kVsat * (1.0 - kScalePerC * (temp_c - 20.0)) * (1.0 - math.exp(-clearance_mm / length))


def calibrated_clearance(model, volts, temp_c):
    return sum(c["a"] * volts ** c["v_power"] * temp_c ** c["t_power"]
               for c in model["coefficients"])


def slope(model, clearance_mm, temp_c):
    def read(d):
        return calibrated_clearance(model, nominal_voltage(d, temp_c), temp_c)
    return (read(clearance_mm + kStepMm) - read(clearance_mm - kStepMm)) / (2.0 * kStepMm)


def main(paths):
    print("| calibration | order | coil | " + " | ".join(f"{d:g} mm" for d in kClearancesMm) + " |")
    print("|---|---:|---:|" + "---:|" * len(kClearancesMm))
    for path in paths:
        model = json.load(open(path))
        for temp_c in kTemperaturesC:
            cells = " | ".join(f"{slope(model, d, temp_c):.3f}" for d in kClearancesMm)
            print(f"| {path} | {model['order']} | {temp_c:g} degC | {cells} |")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit("usage: calibration_slope_alt.py FLEET/wear/calibration.json ...")
    main(sys.argv[1:])
