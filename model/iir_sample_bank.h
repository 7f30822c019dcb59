// SPDX-License-Identifier: MIT
// The sample-level twin of a multichannel core: one IirSampleModel per channel, each with the
// channel's own coefficient set (CoreConfig::channel_config). Channels of the core are independent
// by contract (their own load registers and flags; the shared MAC only orders them in time), so a
// channel's outputs are those of a one-channel core fed that channel's samples alone; the
// co-simulation (tb/) checks that contract against the RTL, and
// tests/model/iir_sample_bank_test.cpp checks this bank against the cycle model.
#pragma once

#include <cstdint>
#include <vector>

#include "filter_json.h"
#include "iir_sample_model.h"

namespace flange::model {

class IirSampleBank {
 public:
  // Throws std::invalid_argument when `config` breaks docs/fixed_point.md.
  explicit IirSampleBank(const CoreConfig& config);

  int channels() const { return static_cast<int>(channels_.size()); }
  // One sample of `channel` (std::out_of_range for a channel outside [0, channels()) or a sample
  // outside the D-bit range).
  SampleResult step(std::int32_t sample, int channel);
  IirSampleModel& channel(int channel);
  void reset();

 private:
  std::vector<IirSampleModel> channels_;
};

}  // namespace flange::model
