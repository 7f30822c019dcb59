// SPDX-License-Identifier: MIT
#include "evidence.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace flange::diagnose::evidence {

std::string fitted_and_scored(double cal_rms_v, double gain_v2, double lower_v2) {
  return fmt::format(
      "fitted on the calibration part (RMS {:.4g} V); on held-out data it lowers the gap's mean "
      "square by {:.3g} V^2 (bootstrap 95 % lower bound {:.3g})",
      cal_rms_v, gain_v2, lower_v2);
}

std::string library_formula_beside(const std::map<std::string, double>& params,
                                   double formula_gain_v2, double free_gain_v2) {
  std::string at;
  for (const auto& [key, value] : params) {
    at += fmt::format("{}{}={:.4g}", at.empty() ? "" : ", ", key, value);
  }
  return fmt::format(
      " (the library's formula, best at {}, lowers the held-out mean square by {:.3g} V^2 "
      "only, {:.0f} % of the free curve's)",
      at, formula_gain_v2, 100.0 * formula_gain_v2 / std::max(free_gain_v2, 1e-30));
}

std::string given_a_free_shape(double formula_left_v, double free_left_v,
                               const std::string& description) {
  return fmt::format(
      "; given a free shape of its class once the other picks were in (the library's formula "
      "left {:.4g} V of held-out RMS, the free shape {:.4g} V): {}",
      formula_left_v, free_left_v, description);
}

std::string confounded(const EffectClass& reported, const EffectClass& other,
                       double margin_share) {
  const std::string& a = reported.follows;
  const std::string& b = other.follows;
  return fmt::format(
      "{} and {} explain the held-out gap alike (within {:.0f} % of the noise variance): "
      "confounded on this protocol; {} is reported, and a session in which {} and {} do not "
      "move together would tell them apart",
      reported.name, other.name, 100.0 * margin_share, reported.name, a,
      a == b ? "the other's shape" : b);
}

std::string dropped(const std::string& name, double cost_v2, double margin_v2) {
  return fmt::format(
      "{} was selected, but the effects selected after it make it unneeded: without it the "
      "held-out gap's mean square changes by {:.3g} V^2, less than the {:.3g} V^2 a pick must "
      "take; not named",
      name, cost_v2, margin_v2);
}

std::string converter_grid(const AdcGrid& grid) {
  return fmt::format(
      "the recorded voltages of both parts lie on one converter grid (estimated from their "
      "spacing): LSB {:.4g} mV, codes {:.6g} to {:.6g} V ({} of {} used, {:.1f} % of samples on "
      "it); {}",
      1e3 * grid.lsb_v, grid.lowest_v, grid.highest_v, grid.codes_used, grid.codes_spanned,
      100.0 * grid.share_on_grid,
      grid.usual_range
          ? fmt::format("the {}-bit grid of the [{}, {}] V range", grid.bits, grid.v_min,
                        grid.v_max)
          : fmt::format("modelled as a {}-bit converter from {:.6g} V", grid.bits, grid.v_min));
}

std::string converter_boundaries(double threshold_lsb, double offset_v, double raw_rms_v,
                                 double placed_rms_v) {
  return fmt::format(
      "; its code boundaries sit {:.2f} LSB from rounding's ({}), which offsets the twin's "
      "voltage by {:.4g} V: placed on the calibration part before any effect was fitted (the "
      "held-out gap RMS {:.4g} -> {:.4g} V by that offset alone)",
      threshold_lsb, std::abs(threshold_lsb) >= 0.4 ? "a truncating converter" : "not rounding's",
      offset_v, raw_rms_v, placed_rms_v);
}

std::string daq_gain(double gain, double offset_v) {
  return fmt::format(
      "; with it, the DAQ software's gain calibration that the grid's spacing shows ({:.5g} "
      "times a usual range's LSB): the recorded voltage is {:.5g} times the twin's {:+.4g} V "
      "(in that held-out figure too)",
      gain, gain, offset_v);
}

std::string quantisation_as_noise(double left_v, double null_rms_v, double lsb_v) {
  return fmt::format(
      "; the twin's converter on it does not reproduce the recorded codes ({:.4g} V left where "
      "the noise alone leaves {:.4g} V: the thresholds sit elsewhere), so the quantisation is "
      "taken as noise of LSB / sqrt(12) = {:.4g} V",
      left_v, null_rms_v, lsb_v / std::sqrt(12.0));
}

std::string mount_motion(double cal_slope_t, double ho_slope_t, double ho_rms_mm) {
  return fmt::format(
      "the gap's sample-to-sample variance grows with the sensor's sensitivity squared "
      "(t = {:.1f} calibration, {:.1f} held-out): clearance motion, not voltage noise; "
      "random phases cannot be fitted, so it adds no shrink (held-out rms_mm {:.3g})",
      cal_slope_t, ho_slope_t, ho_rms_mm);
}

}  // namespace flange::diagnose::evidence
