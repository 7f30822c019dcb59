// SPDX-License-Identifier: MIT
#include "improved_twin.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "criteria.h"
#include "class_fits.h"
#include "effect_classes.h"
#include "improved_twin_reasons.h"
#include "parts.h"
#include "selection.h"
#include "signatures.h"
#include "series_arithmetic.h"
#include "sim_error.h"
#include "table_fit.h"

namespace flange::diagnose {
namespace {

constexpr double kSecondsPerDay = 86400.0;

bool is_converter(const sim::EffectSettings& effect) {
  return effect_class(effect.name).is_converter;
}
bool is_table(const sim::EffectSettings& effect) {
  return effect.name == sim::tabulated_effect_name();
}

// The sensor's age on the table's axis at every sample of a part: the replay's, which places the
// held-out part by the sessions' clocks.
std::vector<double> ages_of(const TwinReplay& replay, double start_age_days) {
  std::vector<double> age(replay.size());
  for (std::size_t i = 0; i < age.size(); ++i) {
    age[i] = start_age_days + (replay.times()[i] + replay.age_offset_s()) / kSecondsPerDay;
  }
  return age;
}

// What the free shapes (and a DAQ gain the converter's placement made) add on a part, with what
// a table the given twin holds already adds there: the new table stands for both.
std::vector<double> added_on(const TwinReplay& replay, const std::vector<double>& free_v,
                             const sim::EffectSettings* given_table) {
  std::vector<double> added = free_v;
  if (given_table == nullptr) return added;
  const std::vector<double> age = ages_of(replay, given_table->params.at("start_age_days"));
  for (std::size_t i = 0; i < added.size(); ++i) {
    added[i] += given_table->table->added_voltage(replay.series().clearance_mm[i],
                                                  replay.series().temp_c[i], age[i]);
  }
  return added;
}

bool class_held(const std::vector<sim::EffectSettings>& effects, const std::string& name) {
  return std::any_of(effects.begin(), effects.end(),
                     [&](const sim::EffectSettings& e) { return e.name == name; });
}

bool any_nonzero(const std::vector<double>& x) {
  return std::any_of(x.begin(), x.end(), [](double v) { return v != 0.0; });
}

// A free-shape pick of a class that follows the sensor's age gives the table its age curve.
bool shapes_follow_age(const Selection& selection) {
  return std::any_of(selection.picks.begin(), selection.picks.end(), [](const Pick& pick) {
    return pick.modelled_index < 0 && !effect_class(pick.finding.name).age_param.empty();
  });
}

// A free shape whose summary gives every parameter of its class's library effect, or whose class
// says which member it is (a lag's mean delay or its mix in volts, a skew's law:
// ClassFit::member_of_shape): that library member, or nothing when the shape lies beyond what the
// twin's effects do.
std::optional<sim::EffectSettings> library_member(const Pick& pick) {
  const FreeShapeFit& shape = *pick.chosen().free_shape;
  ShapeMember member{pick.finding.name, {}};
  if (const auto member_of = class_fit(pick.finding.name).member_of_shape) {
    const std::optional<ShapeMember> of_shape = member_of(shape);
    if (!of_shape) return std::nullopt;
    member = *of_shape;
  } else {
    const sim::EffectSpec& spec =
        sim::effect_catalogue()[static_cast<std::size_t>(sim::catalogue_index(member.effect))];
    for (const sim::ParamSpec& param : spec.params) {
      const auto value = shape.params.find(param.key);
      if (value == shape.params.end()) return std::nullopt;
      member.params[param.key] = value->second;
    }
  }
  try {
    return sim::make_effect_settings(member.effect, member.params, "improved twin");
  } catch (const sim::BadArgument&) {
    return std::nullopt;
  }
}

// A free shape of lines each session has of its own (the mains' lines fitted window by window) as
// its library effect: one line at the mains' frequency with the lines' RMS, what `flange simulate`
// plays; a diagnosis against the twin fits each session's own lines instead (session_lines.h).
std::optional<sim::EffectSettings> session_lines_member(const Pick& pick) {
  const std::map<std::string, double>& params = pick.chosen().free_shape->params;
  const auto rms = params.find("rms_v"), mains = params.find("mains_hz");
  if (rms == params.end() || mains == params.end() || mains->second <= 0.0) return std::nullopt;
  try {
    return sim::make_effect_settings(
        pick.finding.name,
        {{"amplitude_v", std::sqrt(2.0) * rms->second}, {"mains_hz", mains->second},
         {"harmonics", 1.0}},
        "improved twin");
  } catch (const sim::BadArgument&) {
    return std::nullopt;
  }
}

// Free shapes that have a library member (library_member) are held as that member, and the table
// takes what the member leaves of the shape: a shape of the time's course (a lag, a skew) has no
// table over clearance and temperature, its mean member has a formula.
void add_library_members(const Parts& parts, const Selection& selection, ImprovedTwin& out,
                         std::vector<double>& cal_left, std::vector<double>& ho_left) {
  for (const Pick& pick : selection.picks) {
    if (pick.modelled_index >= 0 || !pick.chosen().free_shape) continue;
    if (effect_class(pick.finding.name).lines_of_each_session) {
      if (class_held(out.twin.effects, pick.finding.name)) continue;
      const std::optional<sim::EffectSettings> member = session_lines_member(pick);
      if (!member) continue;
      // The table takes none of the lines: the twin holds them as the session's own.
      const FreeShapeFit& lines = *pick.chosen().free_shape;
      cal_left = minus(cal_left, lines.cal_voltage_v);
      ho_left = minus(ho_left, lines.heldout_voltage_v);
      out.twin.effects.push_back(*member);
      out.members.push_back(pick.finding.name);
      continue;
    }
    const std::optional<sim::EffectSettings> member = library_member(pick);
    if (!member || class_held(out.twin.effects, member->name)) continue;
    const std::vector<sim::EffectSettings> before = replayed_effects(out.twin.effects);
    std::vector<sim::EffectSettings> after = before;
    after.push_back(*member);
    for (const auto& [replay, left] :
         {std::pair{&parts.cal_replay, &cal_left}, std::pair{&parts.ho_replay, &ho_left}}) {
      const std::vector<double> with = replay->voltage(after), without = replay->voltage(before);
      for (std::size_t i = 0; i < left->size(); ++i) (*left)[i] -= with[i] - without[i];
    }
    out.twin.effects.push_back(*member);
    out.members.push_back(pick.finding.name);
  }
}

// The free shapes as one table, replacing any the given twin held.
void add_table(const Parts& parts, const Selection& selection, ImprovedTwin& out) {
  std::vector<double> cal_free = selection.cal_free_v, ho_free = selection.ho_free_v;
  add_library_members(parts, selection, out, cal_free, ho_free);
  std::vector<sim::EffectSettings>& effects = out.twin.effects;
  const auto given = std::find_if(effects.begin(), effects.end(), is_table);
  const sim::EffectSettings* given_table = given == effects.end() ? nullptr : &*given;
  const std::vector<double> cal_added = added_on(parts.cal_replay, cal_free, given_table);
  const std::vector<double> ho_added = added_on(parts.ho_replay, ho_free, given_table);
  if (!any_nonzero(cal_added) && !any_nonzero(ho_added)) return;
  const bool with_age = shapes_follow_age(selection) ||
                        (given_table != nullptr && !given_table->table->age_days.empty());
  std::vector<TabulatedPart> tabulated = {
      {parts.calibration.clearance_mm, parts.calibration.temp_c,
       with_age ? ages_of(parts.cal_replay, 0.0) : std::vector<double>{}, cal_added},
      {parts.heldout.clearance_mm, parts.heldout.temp_c,
       with_age ? ages_of(parts.ho_replay, 0.0) : std::vector<double>{}, ho_added}};
  TableFit fit = fit_effect_table(tabulated, with_age);
  sim::EffectSettings table =
      sim::make_effect_settings(sim::tabulated_effect_name(), {}, "improved twin");
  table.table = std::make_shared<const sim::EffectTable>(std::move(fit.table));
  if (given_table != nullptr) effects.erase(given);
  effects.push_back(std::move(table));
  out.table_misfit_rms_v = fit.misfit_rms_v;
}

HeldFinding held(const EffectFinding& finding, const Selection& selection,
                 const Signatures& signatures, const ImprovedTwin& out,
                 double noise_v) {
  const EffectClass& of = effect_class(finding.name);
  if (of.is_converter) {
    if (signatures.quantisation_as_noise) {
      return {finding.name, HeldAs::kWhiteNoise,
              reasons::held_in_white_noise(signatures.quantised_on->lsb_v)};
    }
    return {finding.name, HeldAs::kConverter,
            reasons::held_as_converter(finding.params.count("calibration_gain") != 0)};
  }
  if (of.is_mount_motion) {
    return {finding.name, HeldAs::kMountMotion,
            reasons::held_as_mount_motion(finding.params.at("rms_mm"))};
  }
  const auto pick = std::find_if(selection.picks.begin(), selection.picks.end(),
                                 [&](const Pick& p) { return p.finding.name == finding.name; });
  const bool member =
      std::find(out.members.begin(), out.members.end(), finding.name) != out.members.end();
  if (of.lines_of_each_session) {
    const bool one_line = pick != selection.picks.end() && pick->modelled_index < 0 && member;
    return {finding.name, HeldAs::kSessionLines,
            one_line ? reasons::held_as_one_session_line(
                           pick->chosen().free_shape->params.at("rms_v"),
                           pick->chosen().free_shape->params.at("mains_hz"))
                     : reasons::held_as_session_lines_effect()};
  }
  if (pick != selection.picks.end() && pick->modelled_index < 0) {
    const double misfit =
        out.table_misfit_rms_v.empty()
            ? 0.0
            : *std::max_element(out.table_misfit_rms_v.begin(), out.table_misfit_rms_v.end());
    // A misfit that alone would take what is left past the explained allowance is not held.
    const double allowed =
        std::sqrt(criteria::kExplainedRatio * criteria::kExplainedRatio - 1.0) * noise_v;
    if (misfit > allowed) {
      return {finding.name, HeldAs::kNotHeld, reasons::not_held_in_table(misfit, allowed)};
    }
    if (member) {
      return {finding.name, HeldAs::kLibraryEffectAndTable,
              reasons::held_as_member_and_table(misfit)};
    }
    return {finding.name, HeldAs::kTable, reasons::held_in_table(misfit)};
  }
  return {finding.name, HeldAs::kLibraryEffect, reasons::held_as_library_effect()};
}

// The clearance and temperature ranges of the calibration part, within the twin file's valid
// ranges.
sim::FittedRanges calibration_ranges(const RecordingSeries& calibration) {
  const auto [x_lo, x_hi] =
      std::minmax_element(calibration.clearance_mm.begin(), calibration.clearance_mm.end());
  const auto [t_lo, t_hi] =
      std::minmax_element(calibration.temp_c.begin(), calibration.temp_c.end());
  const auto clearance = [](double x) { return std::clamp(x, 0.0, sim::kFittedClearanceMaxMm); };
  const auto temperature = [](double t) {
    return std::clamp(t, sim::kFittedTemperatureMinC, sim::kFittedTemperatureMaxC);
  };
  return {clearance(*x_lo), clearance(*x_hi), temperature(*t_lo), temperature(*t_hi)};
}

// Each effect the diagnosis fitted carries the ranges it was fitted on: the calibration part's
// (sim::FittedRanges). The converter, mount motion and lines of each session do not continue a
// curve over them. A table that replaced the given twin's holds both: the ranges they share, or
// none known when the given table's are not known or do not meet the calibration's.
void mark_fitted_ranges(const RecordingSeries& calibration, const sim::TwinConfig& given,
                        sim::TwinConfig& twin) {
  const sim::FittedRanges ranges = calibration_ranges(calibration);
  for (sim::EffectSettings& effect : twin.effects) {
    const bool as_given = std::find(given.effects.begin(), given.effects.end(), effect) !=
                          given.effects.end();
    if (as_given) continue;
    if (is_table(effect)) {
      const auto given_table = std::find_if(given.effects.begin(), given.effects.end(), is_table);
      if (given_table == given.effects.end()) {
        effect.fitted_over = ranges;
      } else if (given_table->fitted_over) {
        effect.fitted_over = sim::overlap(*given_table->fitted_over, ranges);
      }
      continue;
    }
    const EffectClass& of = effect_class(effect.name);
    if (of.is_converter || of.is_mount_motion || of.lines_of_each_session) continue;
    effect.fitted_over = ranges;
  }
}

}  // namespace

ImprovedTwin improved_twin(const Parts& parts, const Selection& selection,
                           const Signatures& signatures, const Diagnosis& diagnosis, const WhiteNoise& white,
                           const sim::TwinConfig& given) {
  ImprovedTwin out;
  out.twin = given;
  const bool selected = !diagnosis.effects.empty();
  if (selected) {
    // The selection's effects, and those of the twin given that the diagnosis does not replay
    // (mount motion).
    out.twin.effects = selection.modelled;
    for (const sim::EffectSettings& effect : given.effects) {
      if (std::none_of(out.twin.effects.begin(), out.twin.effects.end(),
                       [&](const sim::EffectSettings& e) { return e.name == effect.name; })) {
        out.twin.effects.push_back(effect);
      }
    }
    add_table(parts, selection, out);
    if (signatures.vibration) {
      out.twin.effects.push_back(sim::make_effect_settings(
          motion_class(), {{"rms_mm", signatures.vibration->params.at("rms_mm")}}, "improved twin"));
    }
    for (const EffectFinding& finding : diagnosis.effects) {
      out.findings.push_back(held(finding, selection, signatures, out, diagnosis.noise_std_v));
    }
    mark_fitted_ranges(parts.calibration, given, out.twin);
  }
  const bool converter_held =
      std::any_of(out.twin.effects.begin(), out.twin.effects.end(), is_converter);
  out.twin.noise.voltage_std_v = converter_held ? white.analog_std_v : white.effective_std_v;
  // A grid whose codes the twin does not replay: the white noise holds its rounding.
  out.twin.noise.rounding_lsb_v =
      !converter_held && signatures.quantisation_as_noise && signatures.quantised_on
          ? std::min(signatures.quantised_on->lsb_v, std::sqrt(12.0) * out.twin.noise.voltage_std_v)
          : 0.0;
  out.summary = reasons::improved_twin_summary(diagnosis.effects.size(), diagnosis.status,
                                               out.twin.noise.voltage_std_v);
  out.twin.notes = {"made by flange diagnose: " + out.summary};
  for (const HeldFinding& f : out.findings) {
    if (f.held_as == HeldAs::kNotHeld) out.twin.notes.push_back(reasons::not_held_note(f.name, f.note));
  }
  return out;
}

}  // namespace flange::diagnose
