// SPDX-License-Identifier: MIT
#include "iir_sample_model.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <utility>

namespace flange::model {

namespace {

// |value| * 2^shift for |value| < 2^32 and shift <= 31 + 25: at most 2^63, no overflow.
std::uint64_t magnitude_scaled(std::int64_t value, int shift) {
  return static_cast<std::uint64_t>(std::llabs(value)) << shift;
}

// The contract's worst case of one section's sum against the P-bit accumulator (see the header).
bool sum_can_wrap(const CoreConfig& c) {
  const int m = c.section_order;
  const std::uint64_t limit = (std::uint64_t{1} << (c.acc_width - 1)) - 1;
  for (int k = 0; k < c.num_sections; ++k) {
    std::uint64_t bound = std::uint64_t{1} << (c.coef_frac_bits - 1);
    for (int i = 0; i < c.terms(); ++i) {
      const std::int64_t word = c.rom[static_cast<std::size_t>(k * c.terms() + i)];
      const int operand_bits = i <= m ? c.sample_width - 1 : c.sample_width - 1 + c.feedback_shift;
      const std::uint64_t term = magnitude_scaled(word, operand_bits);
      if (term > limit - bound) return true;
      bound += term;
    }
  }
  return false;
}

}  // namespace

IirSampleModel::IirSampleModel(CoreConfig config) : config_(std::move(config)) {
  validate_core_config(config_);
  sample_max_ = static_cast<std::int32_t>((std::int64_t{1} << (config_.sample_width - 1)) - 1);
  sample_min_ = static_cast<std::int32_t>(-(std::int64_t{1} << (config_.sample_width - 1)));
  ext_max_ = (std::int64_t{sample_max_} + 1) * (std::int64_t{1} << config_.feedback_shift) - 1;
  ext_min_ = std::int64_t{sample_min_} * (std::int64_t{1} << config_.feedback_shift);
  can_wrap_ = sum_can_wrap(config_);
  const auto words = static_cast<std::size_t>(config_.num_sections * config_.section_order);
  x_history_.assign(words, 0);
  ext_history_.assign(words, 0);
}

void IirSampleModel::reset() {
  std::fill(x_history_.begin(), x_history_.end(), 0);
  std::fill(ext_history_.begin(), ext_history_.end(), 0);
}

template <int kOrder, bool kWrap>
void IirSampleModel::run(const std::int32_t* in, SampleResult* out, std::size_t n) {
  const int m = kOrder > 0 ? kOrder : config_.section_order;
  const int terms = 2 * m + 1;
  const int sections = config_.num_sections;
  const int fa = config_.coef_frac_bits;
  const int s = config_.feedback_shift;
  const int wrap_shift = 64 - config_.acc_width;
  const std::uint64_t rounding = std::uint64_t{1} << (fa - 1);
  const std::int64_t half = s > 0 ? std::int64_t{1} << (s - 1) : 0;
  const std::int64_t ext_min = ext_min_, ext_max = ext_max_;
  const std::int64_t out_min = sample_min_, out_max = sample_max_;
  const std::int64_t* const rom = config_.rom.data();
  std::int64_t* const x_history = x_history_.data();
  std::int64_t* const ext_history = ext_history_.data();

  for (std::size_t i = 0; i < n; ++i) {
    std::int64_t x = in[i];  // x_k[n]: the filter input, then each section's output
    bool saturated = false;
    for (int k = 0; k < sections; ++k) {
      const std::int64_t* const b = rom + k * terms;  // b[0..M]
      const std::int64_t* const a = b + m;            // a[1..M]: -a, as the ROM holds it
      std::int64_t* const xh = x_history + k * m;     // x_k[n-1-j] at xh[j]
      std::int64_t* const yh = ext_history + k * m;   // y_ext_k[n-1-j] at yh[j]
      // Modulo 2^64, like iir_mac.h's mac(): the sum's low P bits do not depend on the order of
      // the terms, so this order (not the core's issue order) gives the same accumulator.
      std::uint64_t p = rounding + static_cast<std::uint64_t>(b[0] * x);
      for (int j = 1; j <= m; ++j) {
        p += static_cast<std::uint64_t>(b[j] * xh[j - 1]);
        p += static_cast<std::uint64_t>(a[j] * yh[j - 1]);
      }
      // The P-bit two's complement value: shift the sign bit of P to bit 63 and back.
      const std::int64_t acc = kWrap ? static_cast<std::int64_t>(p << wrap_shift) >> wrap_shift
                                     : static_cast<std::int64_t>(p);
      const std::int64_t shifted = acc >> fa;  // arithmetic (C++20)
      const std::int64_t y_ext = std::clamp(shifted, ext_min, ext_max);
      const std::int64_t rounded = (y_ext + half) >> s;
      const std::int64_t y = std::clamp(rounded, out_min, out_max);
      saturated |= (y_ext != shifted) | (y != rounded);
      for (int j = m - 1; j > 0; --j) {
        xh[j] = xh[j - 1];
        yh[j] = yh[j - 1];
      }
      xh[0] = x;
      yh[0] = y_ext;
      x = y;
    }
    out[i] = {static_cast<std::int32_t>(x), saturated};
  }
}

void IirSampleModel::dispatch(const std::int32_t* in, SampleResult* out, std::size_t n) {
  // Biquads (sos sets) and first-order sections get their order at compile time.
  switch (config_.section_order) {
    case 1:
      return can_wrap_ ? run<1, true>(in, out, n) : run<1, false>(in, out, n);
    case 2:
      return can_wrap_ ? run<2, true>(in, out, n) : run<2, false>(in, out, n);
    default:
      return can_wrap_ ? run<0, true>(in, out, n) : run<0, false>(in, out, n);
  }
}

SampleResult IirSampleModel::step(std::int32_t sample) {
  if (sample < sample_min_ || sample > sample_max_) {
    throw std::out_of_range(fmt::format("IirSampleModel: sample {} outside [{}, {}]", sample,
                                        sample_min_, sample_max_));
  }
  SampleResult result;
  dispatch(&sample, &result, 1);
  return result;
}

void IirSampleModel::filter(std::span<const std::int32_t> in, std::span<SampleResult> out) {
  if (in.size() != out.size()) {
    throw std::invalid_argument(
        fmt::format("IirSampleModel::filter: {} inputs but {} outputs", in.size(), out.size()));
  }
  const auto [lo, hi] = std::minmax_element(in.begin(), in.end());
  if (lo != in.end() && (*lo < sample_min_ || *hi > sample_max_)) {
    const std::int32_t bad = *lo < sample_min_ ? *lo : *hi;
    throw std::out_of_range(
        fmt::format("IirSampleModel: sample {} outside [{}, {}]", bad, sample_min_, sample_max_));
  }
  dispatch(in.data(), out.data(), in.size());
}

}  // namespace flange::model
