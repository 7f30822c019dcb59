// SPDX-License-Identifier: MIT
// The sentences the selection and the recognisers write into a finding's evidence or the reasons:
// all the prose of the picks in one place, each from the figures it states.
#pragma once

#include <map>
#include <string>

#include "adc_grid.h"
#include "effect_classes.h"

namespace flange::diagnose::evidence {

// A pick's first sentence: its calibration fit and its held-out gain with the bootstrap bound.
std::string fitted_and_scored(double cal_rms_v, double gain_v2, double lower_v2);

// Beside a free-shape pick: how far its class's library formula (best at `params`) went.
std::string library_formula_beside(const std::map<std::string, double>& params,
                                   double formula_gain_v2, double free_gain_v2);

// A library pick given a free shape of its class once the other picks were in.
std::string given_a_free_shape(double formula_left_v, double free_left_v,
                               const std::string& description);

// Two classes that explain the held-out gap alike, and which recording would tell them apart.
std::string confounded(const EffectClass& reported, const EffectClass& other, double margin_share);

// A pick the backward steps took out.
std::string dropped(const std::string& name, double cost_v2, double margin_v2);

// The converter grid both parts lie on.
std::string converter_grid(const AdcGrid& grid);

// The converter's boundaries placed before the picks, and the held-out RMS that alone took.
std::string converter_boundaries(double threshold_lsb, double offset_v, double raw_rms_v,
                                 double placed_rms_v);

// The DAQ's gain calibration placed with them.
std::string daq_gain(double gain, double offset_v);

// The twin's converter that does not reproduce the recorded codes: the quantisation as noise.
std::string quantisation_as_noise(double left_v, double null_rms_v, double lsb_v);

// Mount motion found from its signature on both parts.
std::string mount_motion(double cal_slope_t, double ho_slope_t, double ho_rms_mm);

}  // namespace flange::diagnose::evidence
