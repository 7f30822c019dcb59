// SPDX-License-Identifier: MIT
#include "iir_core.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "iir_mac.h"

namespace flange::model {

IirCore::IirCore(CoreConfig config) : config_(std::move(config)) {
  validate_core_config(config_);
  const int m = config_.section_order;
  latency_ = config_.terms() + (config_.num_sections - 1) * section_pitch() + kMacLatency + 1;
  sample_max_ = static_cast<std::int32_t>((std::int64_t{1} << (config_.sample_width - 1)) - 1);
  sample_min_ = static_cast<std::int32_t>(-(std::int64_t{1} << (config_.sample_width - 1)));
  ext_max_ = (std::int64_t{sample_max_} + 1) * (std::int64_t{1} << config_.feedback_shift) - 1;
  ext_min_ = std::int64_t{sample_min_} * (std::int64_t{1} << config_.feedback_shift);
  channel_width_ = 1;
  while ((1 << channel_width_) < config_.num_channels) ++channel_width_;
  lr_.assign(static_cast<std::size_t>(config_.num_channels),
             std::vector<std::int64_t>(
                 static_cast<std::size_t>((2 * config_.num_sections + 1) * (m + 1)), 0));
}

IirCore::Rounded IirCore::round_to_sample(std::int64_t y_ext) const {
  const int s = config_.feedback_shift;
  const std::int64_t half = s > 0 ? std::int64_t{1} << (s - 1) : 0;
  const std::int64_t shifted = (y_ext + half) >> s;  // arithmetic (C++20)
  Rounded r;
  r.sample = static_cast<std::int32_t>(std::clamp<std::int64_t>(shifted, sample_min_, sample_max_));
  r.clipped = r.sample != shifted;
  return r;
}

void IirCore::compute(std::int32_t sample, int channel, StepResult& result,
                      std::vector<bool>& clipped) {
  const int m = config_.section_order;
  const int sections = config_.num_sections;
  std::vector<std::int64_t>& lr = lr_[static_cast<std::size_t>(channel)];
  const std::int64_t* const rom = config_.channel_words(channel);
  const int line = m + 1;
  const int terms = config_.terms();
  const int f = config_.coef_frac_bits;
  const int split = config_.split_shift();
  const auto at = [line](int l, int age) { return static_cast<std::size_t>(l * line + age); };

  // EN: every line (history and error) moves one place older; x[n] enters line 0, in the D + s-bit
  // format of the load registers (s zero LSBs).
  for (int l = 0; l <= 2 * sections; ++l) {
    for (int age = m; age > 0; --age) lr[at(l, age)] = lr[at(l, age - 1)];
  }
  lr[0] = std::int64_t{sample} * (std::int64_t{1} << config_.feedback_shift);

  clipped.assign(static_cast<std::size_t>(sections), false);
  result.saturated = false;
  std::int64_t y_ext = 0;
  for (int k = 0; k < sections; ++k) {
    const std::int64_t* const words = rom + k * terms;
    const auto u = [&](int age) { return lr[at(k, age)]; };      // the section's input
    const auto w = [&](int age) { return lr[at(k + 1, age)]; };  // its output history
    const auto e = [&](int age) { return lr[at(sections + 1 + k, age)]; };  // its errors
    // Lo phase: the rounding constant preloaded (2^(F-1) once shifted), the lo words.
    std::uint64_t p = std::uint64_t{1} << (f - 1 + split);
    for (int i = 0; i <= m; ++i) p = mac(p, u(i), words[config_.lo_b(i)]);
    for (int j = 1; j <= m; ++j) p = mac(p, w(j), words[config_.lo_a(j)]);
    // P >>> L (the DSP48E1's Z = P >>> 17), then the hi words and the error feedback.
    p = static_cast<std::uint64_t>(wrap_to_width(p, config_.acc_width) >> split);
    for (int i = 0; i <= m; ++i) p = mac(p, u(i), words[config_.hi_b(i)]);
    for (int j = 1; j <= m; ++j) p = mac(p, w(j), words[config_.hi_a(j)]);
    for (int j = 1; j <= m; ++j) p = mac(p, e(j), words[config_.err(j)]);
    const std::int64_t acc = wrap_to_width(p, config_.acc_width);
    const std::int64_t shifted = acc >> f;  // arithmetic (C++20)
    y_ext = std::clamp(shifted, ext_min_, ext_max_);
    if (y_ext != shifted) clipped[static_cast<std::size_t>(k)] = true;
    lr[at(k + 1, 0)] = y_ext;
    // The low F bits of the sum, less the preload's 2^(F-1): what the rounding dropped.
    lr[at(sections + 1 + k, 0)] =
        static_cast<std::int64_t>(static_cast<std::uint64_t>(acc) & ((std::uint64_t{1} << f) - 1)) -
        (std::int64_t{1} << (f - 1));
  }
  const Rounded y = round_to_sample(y_ext);
  if (y.clipped) clipped.back() = true;
  for (bool c : clipped) result.saturated = result.saturated || c;
  result.sample = y.sample;
  result.channel = channel;
}

void IirCore::schedule(const Event& event) {
  const auto later = [](const Event& a, const Event& b) {
    return a.cycle != b.cycle ? a.cycle < b.cycle : a.kind < b.kind;
  };
  events_.insert(std::upper_bound(events_.begin(), events_.end(), event, later), event);
}

void IirCore::advance(std::uint64_t cycle) {
  if (cycle < now_) {
    throw std::logic_error(fmt::format("IirCore: cycle {} after cycle {}", cycle, now_));
  }
  now_ = cycle;
  while (!events_.empty() && events_.front().cycle <= cycle) {
    const Event event = events_.front();
    events_.pop_front();
    switch (event.kind) {
      case EventKind::kReset:
        settled_ = Pins{};
        any_output_ = false;
        break;
      case EventKind::kClear:
        settled_.overrun = 0;
        settled_.saturation = 0;
        settled_.channel_error = false;
        break;
      case EventKind::kBusyStart:
        settled_.busy = true;
        break;
      case EventKind::kBusyEnd:
        settled_.busy = false;
        break;
      case EventKind::kSaturation:
        settled_.saturation |= std::uint32_t{1} << event.channel;
        break;
      case EventKind::kOverrun:
        settled_.overrun |= std::uint32_t{1} << event.channel;
        break;
      case EventKind::kChannelError:
        settled_.channel_error = true;
        break;
      case EventKind::kOutput:
        settled_.sample = event.value;
        settled_.channel = event.channel;
        valid_cycle_ = event.cycle;
        any_output_ = true;
        break;
    }
  }
  settled_.sample_valid = any_output_ && valid_cycle_ == cycle;
}

Pins IirCore::pins(std::uint64_t cycle) {
  advance(cycle);
  return settled_;
}

std::optional<StepResult> IirCore::strobe(std::uint64_t cycle, std::int32_t sample, int channel) {
  if (sample < sample_min_ || sample > sample_max_) {
    throw std::out_of_range(
        fmt::format("IirCore: sample {} outside [{}, {}]", sample, sample_min_, sample_max_));
  }
  if (channel < 0 || channel >= (1 << channel_width_)) {
    throw std::out_of_range(fmt::format("IirCore: channel {} does not fit the {}-bit channel_i",
                                        channel, channel_width_));
  }
  advance(cycle);
  if (reset_cycle_ == cycle) return std::nullopt;  // reset wins
  if (channel >= config_.num_channels) {
    schedule({cycle + 1, EventKind::kChannelError, 0});
    return std::nullopt;
  }
  if (cycle < ready_cycle_) {
    schedule({cycle + 1, EventKind::kOverrun, 0, channel});
    return std::nullopt;
  }
  StepResult result;
  std::vector<bool> clipped;
  compute(sample, channel, result, clipped);
  result.accept_cycle = cycle;
  result.valid_cycle = cycle + static_cast<std::uint64_t>(latency_);

  // Section k's last term issues T + kS cycles after EN; it is written back kMacLatency cycles
  // later, and a clip shows from the cycle after that.
  const auto terms = static_cast<std::uint64_t>(config_.terms());
  const auto pitch = static_cast<std::uint64_t>(section_pitch());
  for (std::size_t k = 0; k < clipped.size(); ++k) {
    if (clipped[k]) {
      schedule({cycle + terms + k * pitch + kMacLatency + 1, EventKind::kSaturation, 0, channel});
    }
  }
  schedule({cycle + 1, EventKind::kBusyStart, 0});
  schedule({result.valid_cycle, EventKind::kBusyEnd, 0});
  schedule({result.valid_cycle, EventKind::kOutput, result.sample, channel});
  ready_cycle_ = result.valid_cycle;
  return result;
}

StepResult IirCore::step(std::int32_t sample, int channel) {
  if (channel < 0 || channel >= config_.num_channels) {
    throw std::out_of_range(fmt::format("IirCore: channel {} outside [0, {}]", channel,
                                        config_.num_channels - 1));
  }
  const std::uint64_t cycle = std::max(ready_cycle_, now_);
  std::optional<StepResult> result = strobe(cycle, sample, channel);
  if (!result) throw std::logic_error("IirCore::step: the core refused a sample when ready");
  return *result;
}

void IirCore::clear_flags(std::uint64_t cycle) {
  advance(cycle);
  schedule({cycle + 1, EventKind::kClear, 0});
}

void IirCore::reset(std::uint64_t cycle) {
  advance(cycle);
  // Everything that would have become visible after this cycle never happens.
  std::erase_if(events_, [cycle](const Event& e) { return e.cycle > cycle; });
  schedule({cycle + 1, EventKind::kReset, 0});
  for (std::vector<std::int64_t>& lines : lr_) std::fill(lines.begin(), lines.end(), 0);
  ready_cycle_ = cycle + 1;
  reset_cycle_ = cycle;
}

}  // namespace flange::model
