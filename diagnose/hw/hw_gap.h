// SPDX-License-Identifier: MIT
// Attribution of the gap between a float design and its hardware (`flange diagnose --hw`): the
// fixed-point effects are added to the float model one at a time (model/staged_fixed_point.h),
// greedily, each step taking the effect that leaves the smallest remaining gap, and the gap and
// its shrink are recorded at every step, with the poles of the coefficients in use.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "staged_fixed_point.h"

namespace flange::diagnose {

// Poles of a set of sections (the roots of each denominator).
struct PoleCheck {
  double max_radius = 0.0;
  int outside = 0;  // poles with |z| >= 1
  bool stable() const { return outside == 0; }
};
PoleCheck check_poles(const std::vector<model::SectionCoefficients>& sections);

// real - model, in output LSB.
struct GapFigures {
  double rms_lsb = 0.0;
  double max_lsb = 0.0;
  std::optional<double> snr_db;  // 10 log10(sum float^2 / sum gap^2); none when the gap is zero
  std::size_t differing = 0;     // samples where real and model differ
};

struct GapStep {
  std::optional<model::FixedPointEffect> added;  // none for step 0 (the float design)
  model::EffectSet effects;                      // everything on after this step
  GapFigures gap;
  double shrink_pct = 0.0;     // 100 (rms before - rms after) / rms before; 0 when before is 0
  bool changed = false;        // the effect changed the model's output on this stimulus
  PoleCheck poles;             // of the coefficients in use after this step
  std::vector<double> output;  // the staged model's output, LSB
};

struct GapProblem {
  model::StagedFormat format;
  std::vector<model::SectionCoefficients> exact;      // the float design
  std::vector<model::SectionCoefficients> quantised;  // what the hardware holds
  std::vector<double> input;  // analog input, LSB (model::round_input_sample gives the words)
  std::vector<double> real;   // the hardware's output for it, LSB, same length
  std::vector<model::FixedPointEffect> candidates{model::kAllFixedPointEffects.begin(),
                                                  model::kAllFixedPointEffects.end()};
};

struct GapAttribution {
  std::vector<GapStep> steps;  // step 0 is the float design, then one per candidate
  // The first step whose coefficients put a pole on or outside the unit circle.
  std::optional<std::size_t> unstable_step;
};

// Runs 1 + n (n + 1) / 2 staged filters over the input for n candidates. Ties go to the earlier
// candidate. Throws std::invalid_argument when input and real differ in length or are empty.
GapAttribution attribute_gap(const GapProblem& problem);

}  // namespace flange::diagnose
