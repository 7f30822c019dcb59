// SPDX-License-Identifier: MIT
#include "session_lines.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "class_fits.h"
#include "effect_classes.h"
#include "free_shape_fit.h"
#include "series_statistics.h"
#include "series_arithmetic.h"
#include "twin_replay.h"

namespace flange::diagnose {
namespace {

bool of_each_session(const sim::EffectSettings& effect) {
  return effect_class(effect.name).lines_of_each_session;
}

void take_out(RecordingSeries& series, const std::vector<double>& lines_v) {
  for (std::size_t i = 0; i < series.size(); ++i) series.voltage_v[i] -= lines_v[i];
}

}  // namespace

std::optional<SessionLines> take_out_session_lines(const RecordingSeries& calibration,
                                                   const RecordingSeries& heldout,
                                                   const DiagnoseOptions& options,
                                                   double age_offset_s, bool heldout_age_unknown) {
  std::vector<std::string> held;
  for (const sim::EffectSettings& e : options.twin.effects) {
    if (of_each_session(e) && std::find(held.begin(), held.end(), e.name) == held.end()) {
      held.push_back(e.name);
    }
  }
  if (held.empty()) return std::nullopt;
  SessionLines out{calibration, heldout, options, {}};
  std::erase_if(out.options.twin.effects, of_each_session);
  const std::vector<sim::EffectSettings> effects = replayed_effects(options.twin.effects);
  const TwinReplay cal_replay(calibration, options.twin.nominal);
  const TwinReplay ho_replay(heldout, options.twin.nominal, age_offset_s);
  std::vector<std::string> sentences;
  for (const std::string& name : held) {
    for (const FreeShapeFamily& family : class_fit(name).families) {
      const std::vector<double> cal_gap =
          minus(out.calibration.voltage_v, cal_replay.voltage(effects));
      const std::vector<double> ho_gap = minus(out.heldout.voltage_v, ho_replay.voltage(effects));
      const FreeShapeFit lines = fit_free_shape(family, {{out.calibration, cal_replay},
                                                         {out.heldout, ho_replay},
                                                         cal_gap,
                                                         ho_gap,
                                                         heldout_age_unknown});
      take_out(out.calibration, lines.cal_voltage_v);
      take_out(out.heldout, lines.heldout_voltage_v);
      sentences.push_back(fmt::format(
          "{} ({:.3g} V RMS taken out of the calibration recording, {:.3g} V of the held-out one)",
          lines.description, rms_of(lines.cal_voltage_v), rms_of(lines.heldout_voltage_v)));
    }
  }
  const auto joined = [](const std::vector<std::string>& parts, const char* between) {
    std::string all;
    for (const std::string& part : parts) all += (all.empty() ? "" : between) + part;
    return all;
  };
  out.reason = fmt::format(
      "the twin holds {}, whose lines are each session's own: the diagnosis fitted them to the gap "
      "the twin's other effects leave on each recording and took them out before the rest: {}",
      joined(held, ", "), joined(sentences, "; "));
  return out;
}

}  // namespace flange::diagnose
