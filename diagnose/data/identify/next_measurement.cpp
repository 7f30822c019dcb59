// SPDX-License-Identifier: MIT
#include "next_measurement.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "aliased_lines.h"
#include "criteria.h"
#include "effect_classes.h"
#include "fixed_knees.h"
#include "gains_alike_offsets.h"
#include "hypothetical_session.h"
#include "parameter_resolution.h"
#include "series_statistics.h"
#include "series_arithmetic.h"

namespace flange::diagnose {
namespace {

// The smallest span of a sweep that satisfies `tells`, as "the temperature over at least 5 degC
// (20 to 25 degC)": where the sweep that tells was tried.
template <typename Tells>
std::optional<std::string> smallest_sweep(const RecordingSeries& calibration, const Sweep& sweep,
                                          const sim::PolynomialSensorModel& nominal, Tells tells) {
  for (double span : sweep.spans) {
    const RecordingSeries session = hypothetical_session(calibration, sweep.variable, span);
    const TwinReplay replay(session, nominal);
    if (tells(replay)) {
      const SweepRange range = sweep_range(calibration, sweep.variable, span);
      return fmt::format("a session that sweeps the {} over at least {:g} {} ({:.3g} to {:.3g} {})",
                         sweep.variable, span, sweep.unit, range.lowest, range.highest, sweep.unit);
    }
  }
  return std::nullopt;
}

// "X, or Y" over every sweep that tells, or nothing.
template <typename Tells>
std::optional<std::string> sessions_that_tell(const Parts& parts, Tells tells) {
  std::string found;
  for (const Sweep& sweep : sweeps()) {
    auto one = smallest_sweep(parts.calibration, sweep, parts.cal_replay.nominal(), tells);
    if (one) found += (found.empty() ? "" : ", or ") + *one;
  }
  if (found.empty()) return std::nullopt;
  return found;
}

const Candidate* library_candidate(const Step& step, const std::string& name) {
  for (const Candidate& c : step.candidates) {
    if (!c.free_shape && c.fit.settings.name == name) return &c;
  }
  return nullptr;
}

std::string tell_apart(const Parts& parts, const Pick& pick, const std::string& other,
                       double least_v) {
  const EffectClass& a = effect_class(pick.finding.name);
  const EffectClass& b = effect_class(other);
  if (a.lines_of_each_session && b.is_mount_motion) {
    return tell_line_from_motion(parts, pick.finding, other);
  }
  const std::string fallback =
      fmt::format("to tell {} from {}: a session in which {} and {} do not move together", a.name,
                  b.name, a.follows, a.follows == b.follows ? "the other's shape" : b.follows);
  if (pick.chosen().free_shape && pick.chosen().free_shape->also_of_class == other) {
    return tell_fixed_knee_from_compression(parts, pick.finding, other);
  }
  if (pick.chosen().free_shape &&
      pick.chosen().free_shape->family.temperature_alone_also_of == other) {
    return tell_gain_from_offset(pick.finding, other);
  }
  const Candidate* rival = library_candidate(pick.step, other);
  if (pick.chosen().free_shape || rival == nullptr) return fallback;
  const auto tells = [&](const TwinReplay& replay) {
    return rms_of(minus(replay.voltage(pick.chosen().with), replay.voltage(rival->with))) >=
           least_v;
  };
  const std::optional<std::string> sessions = sessions_that_tell(parts, tells);
  if (!sessions) return fallback + " (no sweep tried here separates the fits found)";
  return fmt::format(
      "to tell {} from {}: {} (the fits found here then differ by more than the "
      "{:.2g} V RMS the held-out score resolves)",
      a.name, b.name, *sessions, least_v);
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t k = 0; k < names.size(); ++k) {
    out += (k == 0 ? "" : k + 1 == names.size() ? " and " : ", ") + names[k];
  }
  return out;
}

// The pick's undetermined library parameters, determined by which sweep: one in which they are no
// longer undetermined (parameter_resolution.h, judge_values), the law asked of over the same
// operating range as on the calibration part.
std::string determine(const Parts& parts, const Selection& selection, const Pick& pick,
                      double noise_v) {
  const auto index = static_cast<std::size_t>(pick.modelled_index);
  const sim::EffectSettings& effect = selection.modelled[index];
  std::vector<ModelledValue> values;
  std::vector<std::size_t> open;
  for (const SearchRange& range : effect_class(effect.name).search) {
    if (effect.params.count(range.key) == 0) continue;
    const auto& undetermined = pick.finding.undetermined;
    if (std::find(undetermined.begin(), undetermined.end(), range.key) != undetermined.end()) {
      open.push_back(values.size());
    }
    values.push_back({index, range});
  }
  const RecordingSeries range_session = operating_range_session(parts.calibration);
  const TwinReplay operating_range(range_session, parts.cal_replay.nominal());
  const auto tells = [&](const TwinReplay& replay) {
    for (const ValueJudgement& j :
         judge_values(replay, operating_range, selection.modelled, values, open, noise_v)) {
      if (j.undetermined) return false;
    }
    return true;
  };
  const std::string what =
      fmt::format("to determine {} of {}", joined(pick.finding.undetermined), pick.finding.name);
  const std::optional<std::string> sessions = sessions_that_tell(parts, tells);
  if (sessions) return what + ": " + *sessions;
  return fmt::format("{}: a session in which {} varies more than in this one", what,
                     effect_class(effect.name).follows);
}

std::string visit(const Pick& pick) {
  return fmt::format(
      "to determine {}'s free curve at {}: a session with samples near them (the calibration "
      "part has none)",
      pick.finding.name, joined(pick.finding.undetermined));
}

}  // namespace

std::vector<std::string> next_measurements(const Parts& parts, const Selection& selection) {
  const double noise_v = resolution_noise(selection);
  const double least_v = std::sqrt(criteria::kScoreResolution) * noise_v;
  std::vector<std::string> out;
  for (const Pick& pick : selection.picks) {
    for (const std::string& other : pick.finding.indistinguishable_from) {
      out.push_back(tell_apart(parts, pick, other, least_v));
    }
    if (pick.finding.undetermined.empty()) continue;
    out.push_back(pick.modelled_index >= 0 ? determine(parts, selection, pick, noise_v)
                                           : visit(pick));
  }
  return out;
}

}  // namespace flange::diagnose
