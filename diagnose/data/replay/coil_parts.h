// SPDX-License-Identifier: MIT
// The two parts with the inputs the coil saw in place of the recorded ones, for the free shapes.
// With a late temperature channel modelled (a reading lag, a skew), a class of the temperature
// follows the coil's, which leads the reading; the library's effects see it in the replay already
// (ambient_from_recorded). With a late voltage channel modelled (a skew), the clearance and
// temperature are those the voltage was made at: a free curve is added to the skewed voltage,
// after the chain, so a curve of the recorded clearance would smear a ripple wherever the
// micrometer moves.
#pragma once

#include <memory>
#include <vector>

#include "effect_catalogue.h"
#include "parts.h"

namespace flange::diagnose {

class CoilParts {
 public:
  // The parts behind the delays `modelled` makes; when it makes none, the parts as recorded.
  CoilParts(const Parts& parts, const std::vector<sim::EffectSettings>& modelled);
  RecordedPart calibration() const;
  RecordedPart heldout() const;

 private:
  struct Copies {
    RecordingSeries calibration, heldout;
    std::unique_ptr<TwinReplay> cal_replay, ho_replay;
  };
  const Parts& parts_;
  std::unique_ptr<const Copies> copies_;  // null: the parts as recorded
};

}  // namespace flange::diagnose
