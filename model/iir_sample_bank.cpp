// SPDX-License-Identifier: MIT
#include "iir_sample_bank.h"

#include <fmt/format.h>

#include <stdexcept>

namespace flange::model {

IirSampleBank::IirSampleBank(const CoreConfig& config) {
  validate_core_config(config);
  channels_.reserve(static_cast<std::size_t>(config.num_channels));
  for (int c = 0; c < config.num_channels; ++c) channels_.emplace_back(config.channel_config(c));
}

IirSampleModel& IirSampleBank::channel(int channel) {
  if (channel < 0 || channel >= channels()) {
    throw std::out_of_range(
        fmt::format("IirSampleBank: channel {} outside [0, {}]", channel, channels() - 1));
  }
  return channels_[static_cast<std::size_t>(channel)];
}

SampleResult IirSampleBank::step(std::int32_t sample, int channel) {
  return this->channel(channel).step(sample);
}

void IirSampleBank::reset() {
  for (IirSampleModel& model : channels_) model.reset();
}

}  // namespace flange::model
