// SPDX-License-Identifier: MIT
// The specifications of every effect the twin knows, one per file in this folder; the catalogue
// (effect_catalogue.h) lists them in signal-chain order.
#pragma once

#include "effect.h"

namespace flange::sim {

EffectSpec vibration_effect();          // kMount
EffectSpec thermal_lag_effect();        // kThermal
EffectSpec nonlinearity_effect();       // kSensor
EffectSpec temp_gain_drift_effect();    // kSensor
EffectSpec temp_offset_drift_effect();  // kSensor
EffectSpec ageing_drift_effect();       // kSensor
EffectSpec range_compression_effect();  // kSensor
EffectSpec thermal_lag_volts_effect();  // kSensor, after the sensor's other effects
EffectSpec mains_pickup_effect();       // kWiring
EffectSpec channel_skew_effect();       // kAcquisition
EffectSpec tabulated_effect();          // kAcquisition, before the converter
EffectSpec adc_quantization_effect();   // kAcquisition

}  // namespace flange::sim
