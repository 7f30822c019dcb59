// SPDX-License-Identifier: MIT
// The sentences that explain a verdict (DiagnosisDetail::reasons), each from the figures it states.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "diagnosis.h"
#include "findings.h"
#include "recording_series.h"

namespace flange::diagnose {

// diagnosis.json's word for a status: "explained", "partly explained", "unexplained", "none".
const char* status_text(Status status);
// The same word, for messages and test output.
std::ostream& operator<<(std::ostream& out, Status status);

}  // namespace flange::diagnose

namespace flange::diagnose::reasons {

// The held-out gap before and after the picks, against the white noise.
std::string heldout_summary(double before_v, double after_v, double sigma_v);

// What is left is within the noise over the session but not in its worst window.
std::string missed_in_a_window(double worst_ratio, double from_s, double to_s,
                               double allowed_ratio);

std::string explained();

// Explained where the calibration reaches, with what the continued curves take beyond it.
struct BeyondReach {
  std::size_t within = 0, beyond = 0;  // held-out samples within and beyond
  double temp_lo_c = 0, temp_hi_c = 0, clearance_lo_mm = 0, clearance_hi_mm = 0;  // the reach
  double heldout_temp_lo_c = 0, heldout_temp_hi_c = 0;
  double heldout_clearance_lo_mm = 0, heldout_clearance_hi_mm = 0;
  double left_within_v = 0, left_beyond_v = 0, beyond_share = 0;
};
std::string explained_within_reach(const BeyondReach& b);
// The verdict's scope: "where the calibration reaches (24.9-69.9 C, 2.46-9.46 mm)".
std::string where_the_calibration_reaches(const BeyondReach& b);
// What is left lies beyond the calibration's ranges, with nothing picked that takes most of it.
std::string gap_beyond_reach(const BeyondReach& b);
// The twin leaves the gap at the noise within the calibration's ranges, and the samples beyond
// them lie beyond the ranges its effects `continued` were fitted on (sim::FittedRanges).
std::string none_within_twin_fits(const BeyondReach& b, const std::vector<std::string>& continued);
// Picks beside such a verdict: they change only how the twin continues beyond its fits.
std::string picks_beyond_twin_fits(const std::vector<EffectFinding>& picks);

// The share of the gap above the noise the picks take over the session and in its worse half.
std::string partly_explained(double share, double least_half_share,
                             const std::string& what_is_left);

// What the picks leave against what the noise allows: over the session, or in its worst window.
std::string what_is_left(double left_v, double allowed_v, double worst_v, double from_s,
                         double to_s, double window_allowed_v);

std::string unexplained(bool any_findings);
std::string none();
// A stage of the calibration part above its floor where the held-out part, entering the gap's
// cell, shows no gap.
std::string stage_not_confirmed(const std::string& stage);
// Picks on a held-out gap that was no gap, taking only `taken_pct` of what stood above the noise.
std::string residue_fit(const std::vector<EffectFinding>& picks, double taken_pct);

// The nearest effect's evidence for an "unexplained" verdict.
std::string nearest(bool picked, const EffectFinding& nearest, bool several_picks,
                    const std::string& what_is_left);

// The verdict's noise: the converter grid modelled, or the quantisation taken as noise, or motion.
std::string quantisation_as_noise(double effective_std_v);
std::string converter_grid_modelled(double null_rms_v, double analog_std_v, double lsb_v);
std::string motion_in_the_noise(double verdict_noise_v, double sigma_v);

// The clocks, when they bear on the verdict: the start times were used, or they were missing and
// an age effect was weighed.
std::optional<std::string> clock(const Diagnosis& diagnosis,
                                 const std::vector<EffectFinding>& partial);

// A static function of clearance named where each clearance is reached from one side only.
std::string one_sided_protocol();

// The held-out part barely enters the cell where the calibration gap stands out most.
std::string coverage(std::size_t heldout_samples, const RegionCell& cell);

}  // namespace flange::diagnose::reasons
