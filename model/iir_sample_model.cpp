// SPDX-License-Identifier: MIT
#include "iir_sample_model.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <stdexcept>
#include <utility>

namespace flange::model {

namespace {

// |value| * 2^shift: a C-bit word times the largest D-bit sample (shift D - 1) or history word
// (shift D - 1 + s), below 2^62 since D + s + C <= P <= 64.
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

// Biquad sets (the generator's sos structure) with up to this many sections get a kernel with M and
// K fixed at compile time; everything else runs the general one.
constexpr int kMaxFixedSections = 8;

IirSampleModel::IirSampleModel(CoreConfig config) : config_(std::move(config)) {
  validate_core_config(config_);
  if (config_.num_channels != 1) {
    throw std::invalid_argument(fmt::format(
        "IirSampleModel: one channel only; {} channels take an IirSampleBank (iir_sample_bank.h)",
        config_.num_channels));
  }
  sample_max_ = static_cast<std::int32_t>((std::int64_t{1} << (config_.sample_width - 1)) - 1);
  sample_min_ = static_cast<std::int32_t>(-(std::int64_t{1} << (config_.sample_width - 1)));
  ext_max_ = (std::int64_t{sample_max_} + 1) * (std::int64_t{1} << config_.feedback_shift) - 1;
  ext_min_ = std::int64_t{sample_min_} * (std::int64_t{1} << config_.feedback_shift);
  can_wrap_ = sum_can_wrap(config_);
  kernel_ = choose_kernel();
  partial_.resize(static_cast<std::size_t>(config_.num_sections * config_.section_order));
  reset();
}

void IirSampleModel::reset() {
  // A zero history: only the rounding constant, preloaded into each section's next sum.
  std::fill(partial_.begin(), partial_.end(), 0);
  for (int k = 0; k < config_.num_sections; ++k) {
    partial_[static_cast<std::size_t>(k * config_.section_order)] = std::uint64_t{1}
                                                                    << (config_.coef_frac_bits - 1);
  }
}

template <int kOrder, int kSections, bool kWrap>
void IirSampleModel::run(const std::int32_t* in, SampleResult* out, std::size_t n) {
  constexpr bool kFixed = kOrder > 0;
  const int m = kFixed ? kOrder : config_.section_order;
  const int sections = kFixed ? kSections : config_.num_sections;
  const int terms = 2 * m + 1;
  const int fa = config_.coef_frac_bits;
  const int s = config_.feedback_shift;
  const int wrap_shift = 64 - config_.acc_width;
  const std::uint64_t rounding = std::uint64_t{1} << (fa - 1);
  const std::int64_t half = s > 0 ? std::int64_t{1} << (s - 1) : 0;
  const std::int64_t ext_min = ext_min_, ext_max = ext_max_;
  const std::int64_t out_max = sample_max_;
  // y_ext rounds above sample_max from (sample_max + 1) 2^s - half on (never for s = 0).
  const std::int64_t clip_free_max = std::min(ext_max, ((out_max + 1) << s) - half - 1);
  const auto clip_free_span = static_cast<std::uint64_t>(clip_free_max - ext_min);

  std::array<std::int64_t, kFixed ? kSections*(2 * kOrder + 1) : 1> local_rom{};
  std::array<std::uint64_t, kFixed ? kSections * kOrder : 1> local_partial{};
  const std::int64_t* rom = config_.rom.data();
  std::uint64_t* partial = partial_.data();
  if constexpr (kFixed) {
    std::copy(config_.rom.begin(), config_.rom.end(), local_rom.begin());
    std::copy(partial_.begin(), partial_.end(), local_partial.begin());
    rom = local_rom.data();
    partial = local_partial.data();
  }

  std::int64_t x = 0;  // x_k[n]: the filter input, then each section's output
  bool saturated = false;
  const auto section = [&](int k) {
    const std::int64_t* const b = rom + k * terms;  // b[0..M]
    const std::int64_t* const a = b + m;            // a[1..M]: -a, as the ROM holds it
    std::uint64_t* const z = partial + k * m;
    // Sums modulo 2^64, like iir_mac.h's mac(); the products are exact (D + s + C <= P <= 64).
    const std::uint64_t p = z[0] + static_cast<std::uint64_t>(b[0] * x);
    // The P-bit two's complement value: shift the sign bit of P to bit 63 and back.
    const std::int64_t acc = kWrap ? static_cast<std::int64_t>(p << wrap_shift) >> wrap_shift
                                   : static_cast<std::int64_t>(p);
    const std::int64_t shifted = acc >> fa;  // arithmetic (C++20)
    const std::int64_t y_ext = std::clamp(shifted, ext_min, ext_max);
    // y_ext >= ext_min = sample_min 2^s rounds to >= sample_min: only the upper rail can clip.
    const std::int64_t y = std::min((y_ext + half) >> s, out_max);
    // Either clip, in one unsigned compare: shifted below ext_min, or above the largest y_ext that
    // rounds into D bits (which is at most ext_max, so a first-step clip at the top counts too).
    saturated |= static_cast<std::uint64_t>(shifted - ext_min) > clip_free_span;
    // x_k[n] and y_ext_k[n] go into the sums of samples n+1..n+M.
    for (int j = 0; j + 1 < m; ++j) {
      z[j] = z[j + 1] + static_cast<std::uint64_t>(b[j + 1] * x) +
             static_cast<std::uint64_t>(a[j + 1] * y_ext);
    }
    z[m - 1] = static_cast<std::uint64_t>(b[m] * x) + static_cast<std::uint64_t>(a[m] * y_ext);
    z[0] += rounding;
    x = y;
  };

  for (std::size_t i = 0; i < n; ++i) {
    x = in[i];
    saturated = false;
    if constexpr (kFixed) {
      // Unrolled, so that every index is a constant and the arrays can live in registers.
      [&]<int... k>(std::integer_sequence<int, k...>) { (section(k), ...); }
      (std::make_integer_sequence<int, kSections>{});
    } else {
      for (int k = 0; k < sections; ++k) section(k);
    }
    out[i] = {static_cast<std::int32_t>(x), saturated};
  }

  if constexpr (kFixed) std::copy(local_partial.begin(), local_partial.end(), partial_.begin());
}

template <bool kWrap>
IirSampleModel::Kernel IirSampleModel::biquad_kernel(int sections) {
  switch (sections) {
    case 1:
      return &IirSampleModel::run<2, 1, kWrap>;
    case 2:
      return &IirSampleModel::run<2, 2, kWrap>;
    case 3:
      return &IirSampleModel::run<2, 3, kWrap>;
    case 4:
      return &IirSampleModel::run<2, 4, kWrap>;
    case 5:
      return &IirSampleModel::run<2, 5, kWrap>;
    case 6:
      return &IirSampleModel::run<2, 6, kWrap>;
    case 7:
      return &IirSampleModel::run<2, 7, kWrap>;
    case 8:
      return &IirSampleModel::run<2, 8, kWrap>;
    default:
      return &IirSampleModel::run<0, 0, kWrap>;
  }
}
static_assert(kMaxFixedSections == 8, "biquad_kernel has one case per fixed section count");

IirSampleModel::Kernel IirSampleModel::choose_kernel() const {
  if (config_.section_order == 2 && config_.num_sections <= kMaxFixedSections) {
    return can_wrap_ ? biquad_kernel<true>(config_.num_sections)
                     : biquad_kernel<false>(config_.num_sections);
  }
  return can_wrap_ ? &IirSampleModel::run<0, 0, true> : &IirSampleModel::run<0, 0, false>;
}

SampleResult IirSampleModel::step(std::int32_t sample) {
  if (sample < sample_min_ || sample > sample_max_) {
    throw std::out_of_range(fmt::format("IirSampleModel: sample {} outside [{}, {}]", sample,
                                        sample_min_, sample_max_));
  }
  SampleResult result;
  // The general kernel works on the members in place; a fixed one would copy them in and out.
  if (can_wrap_) {
    run<0, 0, true>(&sample, &result, 1);
  } else {
    run<0, 0, false>(&sample, &result, 1);
  }
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
  (this->*kernel_)(in.data(), out.data(), in.size());
}

}  // namespace flange::model
