// SPDX-License-Identifier: MIT
// The effect classes as data: one entry per class of the twin's library, holding everything the
// diagnosis knows of it. No code outside effect_classes.cpp compares a class's name; the stages
// ask the table. Adding a class is adding its effect to sim/src/effects/, one entry here and its
// free-shape families (diagnose/data/README.md, "Adding an effect class").
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "channel_skew_law.h"
#include "effect_catalogue.h"

namespace flange::diagnose {

// How the diagnosis finds a class in the data.
enum class Identification {
  kByBias,       // fitted: its formula (or a free shape) lowers the gap on held-out data
  kBySignature,  // recognised from what it does to the gap's variance or to the recorded codes
};

// One parameter the library fit varies, and the range searched: inside the catalogue's valid
// range, narrower where the full range is physically absurd for a bench.
struct SearchRange {
  std::string key;
  double lo = 0.0, hi = 0.0;
};

// How a class's settings make a channel late. A skew between the channels on the session's clock
// (sim::ChannelSkewLaw): where it is > 0 the temperature at t is the coil's at t - skew(t), where
// < 0 the voltage at t was made at t + skew(t). Or a first-order lag of the temperature reading
// (temperature_lag_tau_s > 0).
struct ChannelDelay {
  sim::ChannelSkewLaw skew{};
  double temperature_lag_tau_s = 0.0;

  // Whether the skew makes (or, drifting, may make) the temperature channel late; the voltage.
  bool temperature_late() const { return skew.skew_s > 0.0 || skew.drifts(); }
  bool voltage_late() const { return skew.skew_s < 0.0 || skew.drifts(); }
};

// A law of the temperature whose level at one temperature the data fix where its slope is left
// open (identify/recorded_level.h): the effect at `temp_c` under `params`, reported as `key`.
struct TemperatureLevel {
  std::string key;
  double (*at)(const sim::ParamValues& params, double temp_c) = nullptr;
};

class SelftestDraw;

struct EffectClass {
  std::string name;  // its effect in the twin's library (sim::effect_catalogue)
  Identification identification = Identification::kByBias;
  // Reported as a noise-type effect although fitted by its bias (a tone whose phase is each
  // session's own), with this phrase added to a pick's evidence.
  bool reported_as_noise = false;
  std::string pick_note{};
  // The library fit's free parameters with their ranges (its fitter, and its free-shape families,
  // are in candidates/class_fits.h).
  std::vector<SearchRange> search{};
  // Solved by least squares inside every other class's fit (profiled out) rather than held
  // there: a class linear in its values that trades against others along a narrow valley.
  bool profiled_in_other_fits = false;
  // What its effect follows, for saying which recording tells two classes apart.
  std::string follows{};
  // Its level at the recorded temperature, for a linear law of the temperature.
  std::optional<TemperatureLevel> level{};
  // Replayed at the sensor's age: the parameter that carries the age from one session to the
  // next (empty for classes that depend on time only through its differences).
  std::string age_param{};
  // A function of the clearance alone: on a protocol that reaches each clearance from one side
  // only it cannot be told from a hysteresis (outside the library).
  bool function_of_clearance_alone = false;
  // The converter: its grid is found from the recorded codes (input/adc_grid.h), and its code
  // boundaries may be placed before the picks (noise/converter_boundaries.h).
  bool is_converter = false;
  // Mount motion: found from how the gap's variance follows the sensitivity
  // (noise/vibration_signature.h).
  bool is_mount_motion = false;
  // Lines each session has of its own (the mains: its phase at a session's start, and with a
  // wandering grid its amplitude window by window). A twin that holds the class is not replayed
  // with it: a diagnosis against that twin takes each part's own lines, fitted by the class's
  // free shape, out of its recording (candidates/session_lines.h).
  bool lines_of_each_session = false;
  // Its effect has no level of its own, so that an error in it carries none from the calibration
  // session to the held-out one: a skew is the voltage's rate of change times a delay, which
  // averages out over the micrometer's moves, and the mains' lines are fitted on each session.
  // A level between the sessions may be chosen on the held-out part beside such picks
  // (FreeShapeInputs::no_level_carried).
  bool carries_no_level = false;
  // The channel delays a setting of this class makes.
  ChannelDelay (*channel_delay)(const sim::EffectSettings&) = nullptr;
  // The blind self-test's draw of its parameters: each range's low end moves a bench recording's
  // voltage by about the thesis's repeatability (docs/diagnose.md, "How it is checked").
  sim::ParamValues (*selftest_draw)(SelftestDraw& draw) = nullptr;
};

// Every class, in the order their free-shape families are scored.
const std::vector<EffectClass>& effect_classes();

// The class of library effect `name`. Throws std::out_of_range for a name not in the table.
const EffectClass& effect_class(const std::string& name);

// The same, or none for a name not in the table.
const EffectClass* find_effect_class(const std::string& name);

// The classes fitted by their bias, in the twin's catalogue order (the order library candidates
// are fitted and weighed in).
std::vector<std::string> bias_classes_in_catalogue_order();

// The delays `effect` makes (zero for classes without any).
ChannelDelay channel_delay_of(const sim::EffectSettings& effect);

// Each session's own: mount motion, and lines of each session. A diagnosis does not replay them
// on another session (a replayed realisation would add to the gap, not take from it): it draws
// the motion afresh and fits each session's lines.
bool each_sessions_own(const sim::EffectSettings& effect);

// `effects` without those that are each session's own: what a diagnosis replays.
std::vector<sim::EffectSettings> replayed_effects(const std::vector<sim::EffectSettings>& effects);

// The converter class's name (the one entry with is_converter), and mount motion's.
const std::string& converter_class();
const std::string& motion_class();

}  // namespace flange::diagnose
