// SPDX-License-Identifier: MIT
// The command-line form of an effect: NAME or NAME:key=value[,key=value...].
#pragma once

#include <string>

#include "effect.h"

namespace flange::sim {

struct EffectArgument {
  std::string name;
  ParamValues values;  // only the keys given; checked against the effect later
};

// Splits one --effect argument. Throws BadArgument with one line naming the argument when it is
// malformed: empty name, a pair without '=', an empty key, a value that is not a number, or a
// key given twice.
EffectArgument parse_effect_argument(const std::string& text);

}  // namespace flange::sim
