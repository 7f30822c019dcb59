// SPDX-License-Identifier: MIT
// The sim-to-real gap diagnosis of a recording: where the gap lies, which unmodelled effect of
// the twin's library explains it, and how far it shrinks on held-out data. `flange diagnose`
// writes it as diagnosis.json and an HTML report; `flange diagnose --selftest` calls it blind.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "recording_series.h"
#include "sensor_twin.h"

namespace flange::diagnose {

struct DiagnoseOptions {
  // The twin the recording is compared with; its effects are the ones already modelled.
  // Default: the nominal eq. 3.14 model with the noise level estimated from the data.
  sim::TwinConfig twin;
  bool estimate_noise = true;  // estimate twin.noise.voltage_std_v from the data
  int bootstrap_rounds = 100;  // for confidence intervals and effect inclusion frequencies
  std::uint64_t seed = 1;      // bootstrap resampling
};

// A law of the temperature inside the recording (identify/recorded_level.h): the effect at the
// calibration part's mean recorded temperature, which the data fix even where the law's slope is
// undetermined, with its resolution (infinite where the data do not fix it either).
struct EffectLevel {
  std::string key;          // "gain_change" (relative: the gain's factor less 1), "offset_v" (V)
  double temp_c = 0.0;      // where: the calibration part's mean recorded temperature
  double value = 0.0;
  double resolution = 0.0;  // in the level's unit
};

struct EffectFinding {
  std::string name;                      // an effect of the twin's library
  std::map<std::string, double> params;  // fitted on the calibration part only
  double heldout_rms_before = 0.0;       // voltage gap RMS on held-out data, V
  double heldout_rms_after = 0.0;        // ... once this and the effects before it are added
  double shrink_pct = 0.0;               // 100 * (before - after) / before
  double inclusion = 0.0;                // share of bootstrap rounds that selected its class, 0..1
  bool noise_type = false;               // identified from its signature, not by a bias it removes
  std::string evidence;                  // one sentence: why it was selected
  // A bias-type pick: the held-out gap RMS with every selected effect but this one, V (what the
  // final model needs it for; 0 for noise types).
  double heldout_rms_without = 0.0;
  // What the data tell of its parameters (identify/parameter_resolution.h): each fitted
  // parameter's resolution (the change the data can tell from the fitted value, with the other
  // fitted parameters compensating; infinite when nothing in the data moves with it), the
  // parameters the data cannot determine (held in `params` only so that the effect can be
  // replayed: any value the data allow would do), and those whose value lies at the edge of the
  // search, reported as a bound ("<= -39.5").
  std::map<std::string, double> resolution{};
  std::vector<std::string> undetermined{};
  std::map<std::string, std::string> bounds{};
  // A law of the temperature's level inside the recording (its class's TemperatureLevel).
  std::optional<EffectLevel> level{};
  // The classes whose candidates left the held-out gap within the tie criterion of this one's in
  // the round that picked it: the data cannot tell them from it.
  std::vector<std::string> indistinguishable_from{};
  // How far to trust that its class is in the data, 0..1 (identify/confidence.h): claims made
  // with confidence >= p were right at least a fraction p of the time on blind pairs.
  double confidence = 0.0;
};

// The verdict (verdict/verdict.h decides it; reasons::status_text gives its words):
// explained (what the selected effects leave is within 10 % of the noise), partly explained
// (they leave more, but take at least 90 % of the held-out gap above the noise), unexplained, or
// none.
enum class Status { kExplained, kPartlyExplained, kUnexplained, kNone };

struct Diagnosis {
  Status status = Status::kNone;
  // Where the status holds: "" over the whole held-out session; else a phrase such as "where the
  // calibration reaches (24.9-69.9 C, 2.46-9.46 mm)", when the gap beyond that was left open.
  std::string scope;
  std::vector<EffectFinding> effects;  // selected, in selection order (empty unless explained,
                                       // fully or partly)
  std::string stage;                   // the stage where the gap first appears
  double heldout_rms_before = 0.0;     // V, nominal twin against the held-out recording
  double heldout_rms_after = 0.0;      // V, with every selected effect
  double noise_std_v = 0.0;            // V, the twin's white noise the verdict compares with
  // "unexplained": the library effect the diagnosis came nearest to (the first it selected, or
  // the candidate that lowered the held-out gap most when none was significant), with its
  // held-out RMS before and after it and a sentence on how far that is from explained.
  std::optional<EffectFinding> nearest;
  // How the two parts' clocks relate (docs/diagnose.md, "Sessions and time"): "one clock" (the
  // held-out times continue the calibration part's), "start times" (both sessions' starts given)
  // or "unknown" (the held-out clock restarts and no start times: each session is taken to start
  // at the same age). heldout_starts_after_s: the held-out t_s = 0 less the calibration's.
  std::string clock = "unknown";
  std::optional<double> heldout_starts_after_s;
  // What the data hold constant or too coarse to fit a law of it (input/degenerate_data.h), one
  // sentence each: a verdict on such data says only what one operating point can tell.
  std::vector<std::string> degenerate;
  // What recording would separate the classes the data cannot tell apart or determine the
  // parameters they leave open (reasons/next_measurement.h), one sentence each.
  std::vector<std::string> next_measurement;
};

// Fits on `calibration`, scores on `heldout`; both must share a sample rate and carry the
// reference clearance. Throws InputError (input_error.h) on mismatched or too-short data.
Diagnosis diagnose(const RecordingSeries& calibration, const RecordingSeries& heldout,
                   const DiagnoseOptions& options);

}  // namespace flange::diagnose
