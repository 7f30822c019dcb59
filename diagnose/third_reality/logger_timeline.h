// SPDX-License-Identifier: MIT
// When the third bench's logger samples and what it writes down: both channels are sampled at
// the nominal instants k / fs, each row is stamped with the logger's clock read a little late or
// early (normal jitter, clipped to a third of a step so the stamps still rise; the first row is
// stamped 0, where the logger's clock starts), and rows are lost in bursts (a busy logger drops
// what arrives while it writes; never the first row).
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <vector>

#include "third_random.h"

namespace flange::third_reality {

struct LoggerPlan {
  double jitter_s = 0.0;       // standard deviation of the stamp jitter, s
  double drop_fraction = 0.0;  // the share of rows lost, 0-0.02
  int longest_burst = 1;       // rows lost in a row, at most
  double seed = 1.0;
};

LoggerPlan draw_logger_plan(double fs_hz, ThirdRandom& random);

struct LoggerTimeline {
  std::vector<double> instant_s;  // when each kept row was sampled
  std::vector<double> stamp_s;    // what the logger wrote for it
  std::size_t dropped = 0;        // rows lost
};

// The rows of a session of `duration_s` at `fs_hz`; `with_logger` false: every row, stamped
// exactly (to size effects on the sampling itself).
LoggerTimeline logger_timeline(const LoggerPlan& plan, double fs_hz, double duration_s,
                               bool with_logger);

nlohmann::json logger_plan_json(const LoggerPlan& plan);

}  // namespace flange::third_reality
