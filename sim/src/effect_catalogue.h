// SPDX-License-Identifier: MIT
// Every effect the twin knows, in the order a sample passes them, and the checks that turn a
// name and key=value pairs into validated settings.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "effect.h"
#include "fitted_ranges.h"

namespace flange::sim {

// All effects in signal-chain order (docs/sensor_twin.md, "Signal chain").
const std::vector<EffectSpec>& effect_catalogue();

// Position of `name` in the catalogue, or -1 when there is no such effect.
int catalogue_index(const std::string& name);

// Where in the twin's chain the catalogue's effect `name` acts (name must be in the catalogue).
ChainStage chain_stage_of(const std::string& name);

// The effect that replays a table (effects/tabulated.cpp): the one whose settings carry one.
inline const char* tabulated_effect_name() { return "tabulated"; }

// "vibration, thermal_lag, ...": for error messages and help.
std::string effect_names();

// An effect switched on, with a value for every one of its parameters.
struct EffectSettings {
  std::string name;
  ParamValues params;
  // The tabulated effect's table (twin file only); null for every other effect.
  std::shared_ptr<const EffectTable> table{};
  // The ranges of the recordings its parameters were fitted on, where known (twin file only; the
  // twin plays the effect alike everywhere).
  std::optional<FittedRanges> fitted_over{};
  bool operator==(const EffectSettings& other) const {
    return name == other.name && params == other.params && fitted_over == other.fitted_over &&
           (table == other.table || (table && other.table && *table == *other.table));
  }
};

// Settings for effect `name`: its defaults, replaced by `values`. Throws BadArgument with one
// line starting with `where` (e.g. "--effect mains_pickup" or "twin.json: effects[2]") when the
// name or a key is unknown, a value is not finite or outside its range, an integer parameter has
// a fraction, or the parameters do not go together.
EffectSettings make_effect_settings(const std::string& name, const ParamValues& values,
                                    const std::string& where);

// The range of a parameter as printed in messages and docs: "[0, 1] V".
std::string describe_range(const ParamSpec& param);

// Builds the effect; `twin_seed` is the twin's seed, from which the effect takes its own stream
// (so switching other effects on or off leaves its random numbers unchanged).
std::unique_ptr<Effect> make_effect(const EffectSettings& settings, double v_min_v, double v_max_v,
                                    std::uint64_t twin_seed);

}  // namespace flange::sim
