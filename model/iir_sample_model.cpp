// SPDX-License-Identifier: MIT
#include "iir_sample_model.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <utility>

#include "iir_sample_vector.h"

namespace flange::model {

namespace {

// GCC and Clang's 128-bit integers, for bounds that need 64 bits plus a few.
__extension__ typedef unsigned __int128 u128;
__extension__ typedef __int128 i128;

// The largest magnitudes of a section's terms under the contract, for any history: |u|, |w| <=
// 2^(D-1+s) (x << s and clipped y_ext), |e| <= 2^(F-1).
struct SectionBounds {
  u128 lo = 0;         // |lo|, preload included
  u128 acc = 0;        // |acc| = |(lo >>> L) + hi terms|
  u128 merged = 0;     // |2^(F-1+L) + sum |c| u + sum |E| 2^L e|, every partial sum included
  u128 lo_folded = 0;  // |lo - 2^(F-1) sum E 2^L|: the vector kernel's lo (iir_sample_vector.h)
};

u128 magnitude(std::int64_t v) {
  return v < 0 ? static_cast<u128>(-static_cast<i128>(v)) : static_cast<u128>(v);
}

SectionBounds section_bounds(const CoreConfig& c, const std::int64_t* words) {
  const int m = c.section_order;
  const int split = c.split_shift();
  const u128 signal = u128{1} << (c.sample_width - 1 + c.feedback_shift);
  const u128 error = u128{1} << (c.coef_frac_bits - 1);
  SectionBounds b;
  b.lo = u128{1} << (c.coef_frac_bits - 1 + split);
  b.merged = b.lo;
  u128 hi = 0;
  for (int i = 0; i <= m; ++i) {
    b.lo += magnitude(words[c.lo_b(i)]) * signal;
    hi += magnitude(words[c.hi_b(i)]) * signal;
    b.merged += magnitude((words[c.hi_b(i)] << split) + words[c.lo_b(i)]) * signal;
  }
  for (int j = 1; j <= m; ++j) {
    b.lo += magnitude(words[c.lo_a(j)]) * signal;
    hi += magnitude(words[c.hi_a(j)]) * signal + magnitude(words[c.err(j)]) * error;
    b.merged += magnitude((words[c.hi_a(j)] << split) + words[c.lo_a(j)]) * signal +
                (magnitude(words[c.err(j)]) << split) * error;
  }
  b.acc = (b.lo >> split) + 1 + hi;
  b.lo_folded = b.lo;
  for (int j = 1; j <= m; ++j) b.lo_folded += (magnitude(words[c.err(j)]) * error) << split;
  return b;
}

bool can_wrap(const CoreConfig& c) {
  const u128 limit = (u128{1} << (c.acc_width - 1)) - 1;
  for (int k = 0; k < c.num_sections; ++k) {
    const SectionBounds b = section_bounds(c, c.rom.data() + k * c.terms());
    if (b.lo > limit || b.acc > limit) return true;
  }
  return false;
}

// The vector kernel's sums modulo 2^52 are exact when sign-extended from bit 51.
bool fits_52_bits(const CoreConfig& c) {
  const u128 limit = (u128{1} << 51) - 1;
  for (int k = 0; k < c.num_sections; ++k) {
    const SectionBounds b = section_bounds(c, c.rom.data() + k * c.terms());
    if (b.lo_folded > limit || b.acc > limit) return false;
  }
  return true;
}

bool merged_fits_int64(const CoreConfig& c) {
  const u128 limit = (u128{1} << 63) - 1;
  for (int k = 0; k < c.num_sections; ++k) {
    if (section_bounds(c, c.rom.data() + k * c.terms()).merged > limit) return false;
  }
  return true;
}

// Merged and vector kernels with M and K fixed at compile time: biquads (and first-order
// sections) with up to this many sections. Everything else runs the general merged kernel.
constexpr int kMaxFixedSections = 8;

bool is_vector(SampleKernel kernel) {
  return kernel == SampleKernel::kVector || kernel == SampleKernel::kVectorMerged;
}

}  // namespace

const char* to_string(SampleKernel kernel) {
  switch (kernel) {
    case SampleKernel::kAuto:
      return "auto";
    case SampleKernel::kTwoPhase:
      return "two-phase";
    case SampleKernel::kMerged:
      return "merged";
    case SampleKernel::kVector:
      return "vector";
    case SampleKernel::kVectorMerged:
      return "vector-merged";
  }
  return "?";
}

// What every kernel needs besides the words, from the config.
struct IirSampleModel::Limits {
  int m, sections, split, f, s, wrap_shift;
  std::int64_t ext_min, ext_max, out_max, half_s, half_f, mask_f;
  std::uint64_t span_mid;   // y_ext - ext_min beyond this: a section before the last clipped
  std::uint64_t span_last;  // beyond this the last section clipped, or its rounding did

  explicit Limits(const IirSampleModel& model) {
    const CoreConfig& c = model.config_;
    m = c.section_order;
    sections = c.num_sections;
    split = c.split_shift();
    f = c.coef_frac_bits;
    s = c.feedback_shift;
    wrap_shift = 64 - c.acc_width;
    ext_min = model.ext_min_;
    ext_max = model.ext_max_;
    out_max = model.sample_max_;
    half_s = s > 0 ? std::int64_t{1} << (s - 1) : 0;
    half_f = std::int64_t{1} << (f - 1);
    mask_f = (std::int64_t{1} << f) - 1;
    span_mid = static_cast<std::uint64_t>(ext_max - ext_min);
    // y_ext rounds above sample_max from (sample_max + 1) 2^s - half on (never for s = 0), and
    // y_ext >= ext_min = sample_min 2^s rounds to >= sample_min: only the upper rail can clip.
    const std::int64_t clip_free_max = std::min(ext_max, ((out_max + 1) << s) - half_s - 1);
    span_last = static_cast<std::uint64_t>(clip_free_max - ext_min);
  }
};

bool IirSampleModel::kernel_available(const CoreConfig& config, SampleKernel kernel) {
  switch (kernel) {
    case SampleKernel::kAuto:
    case SampleKernel::kTwoPhase:
      return true;
    case SampleKernel::kMerged:
      return !can_wrap(config) && merged_fits_int64(config);
    case SampleKernel::kVector:
      return vector::supported(config, vector::Sums::kSplit) && !can_wrap(config) &&
             fits_52_bits(config);
    case SampleKernel::kVectorMerged:
      return vector::supported(config, vector::Sums::kMerged) && !can_wrap(config) &&
             merged_fits_int64(config);
  }
  return false;
}

namespace {

// `kernel`, or for kAuto the fastest kernel that computes `config` exactly on this machine: a
// vector kernel (the merged sums first where merged_preferred), then the merged one, else the
// two-phase one. Throws std::invalid_argument when `kernel` cannot compute `config`.
SampleKernel chosen_kernel(const CoreConfig& config, SampleKernel kernel) {
  if (kernel == SampleKernel::kAuto) {
    const SampleKernel first_vector =
        vector::merged_preferred() ? SampleKernel::kVectorMerged : SampleKernel::kVector;
    const SampleKernel second_vector =
        first_vector == SampleKernel::kVector ? SampleKernel::kVectorMerged : SampleKernel::kVector;
    if (IirSampleModel::kernel_available(config, first_vector)) return first_vector;
    if (IirSampleModel::kernel_available(config, second_vector)) return second_vector;
    if (IirSampleModel::kernel_available(config, SampleKernel::kMerged)) {
      return SampleKernel::kMerged;
    }
    return SampleKernel::kTwoPhase;
  }
  if (!IirSampleModel::kernel_available(config, kernel)) {
    throw std::invalid_argument(
        fmt::format("IirSampleModel: the {} kernel cannot compute {} exactly{}", to_string(kernel),
                    config.name, is_vector(kernel) ? " (or this CPU lacks AVX-512)" : ""));
  }
  return kernel;
}

// Per section the merged words c_b[0..M] (c = H 2^L + W), c_a[1..M] and E[1..M] 2^L.
std::vector<std::int64_t> merged_words(const CoreConfig& config) {
  const int m = config.section_order;
  const int split = config.split_shift();
  std::vector<std::int64_t> merged;
  for (int k = 0; k < config.num_sections; ++k) {
    const std::int64_t* w = config.rom.data() + k * config.terms();
    for (int i = 0; i <= m; ++i) {
      merged.push_back(w[config.hi_b(i)] * (std::int64_t{1} << split) + w[config.lo_b(i)]);
    }
    for (int j = 1; j <= m; ++j) {
      merged.push_back(w[config.hi_a(j)] * (std::int64_t{1} << split) + w[config.lo_a(j)]);
    }
    for (int j = 1; j <= m; ++j) merged.push_back(w[config.err(j)] * (std::int64_t{1} << split));
  }
  return merged;
}

}  // namespace

IirSampleModel::IirSampleModel(CoreConfig config, SampleKernel kernel)
    : config_(std::move(config)) {
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
  can_wrap_ = can_wrap(config_);
  kernel_ = chosen_kernel(config_, kernel);

  const int m = config_.section_order;
  // The merged words also serve the vector kernel's short blocks (all kernels share the state).
  if (kernel_ != SampleKernel::kTwoPhase && merged_fits_int64(config_)) {
    merged_ = merged_words(config_);
    const auto pick = [this]<int kOrder>() -> MergedRun {
      switch (config_.num_sections) {
        case 1:
          return &IirSampleModel::run_merged<kOrder, 1>;
        case 2:
          return &IirSampleModel::run_merged<kOrder, 2>;
        case 3:
          return &IirSampleModel::run_merged<kOrder, 3>;
        case 4:
          return &IirSampleModel::run_merged<kOrder, 4>;
        case 5:
          return &IirSampleModel::run_merged<kOrder, 5>;
        case 6:
          return &IirSampleModel::run_merged<kOrder, 6>;
        case 7:
          return &IirSampleModel::run_merged<kOrder, 7>;
        case 8:
          return &IirSampleModel::run_merged<kOrder, 8>;
        default:
          return &IirSampleModel::run_merged<0, 0>;
      }
    };
    static_assert(kMaxFixedSections == 8, "one case per fixed section count");
    merged_run_ = m == 2   ? pick.template operator()<2>()
                  : m == 1 ? pick.template operator()<1>()
                           : &IirSampleModel::run_merged<0, 0>;
  }
  if (is_vector(kernel_)) {
    plan_ = std::make_shared<const vector::Plan>(vector::make_plan(
        config_, kernel_ == SampleKernel::kVector ? vector::Sums::kSplit : vector::Sums::kMerged));
  }
  history_.assign(static_cast<std::size_t>((2 * config_.num_sections + 1) * m), 0);
}

void IirSampleModel::reset() { std::fill(history_.begin(), history_.end(), 0); }

// Moves a line one place older: `newest` becomes age 1.
template <int kOrder>
static inline void push_line(std::int64_t* line, int m, std::int64_t newest) {
  const int order = kOrder > 0 ? kOrder : m;
  for (int age = order; age > 1; --age) line[age - 1] = line[age - 2];
  line[0] = newest;
}

template <int kOrder, int kSections>
void IirSampleModel::run_merged(const std::int32_t* in, SampleResult* out, std::size_t n) {
  constexpr bool kFixed = kOrder > 0;
  const Limits lim(*this);
  const int m = kFixed ? kOrder : lim.m;
  const int sections = kFixed ? kSections : lim.sections;
  const int words = 3 * m + 1;
  const int total_shift = lim.split + lim.f;
  const std::int64_t preload = std::int64_t{1} << (lim.f - 1 + lim.split);

  // With M and K fixed, the words and the history live in local arrays the compiler keeps in
  // registers; otherwise the members are used in place.
  std::array<std::int64_t, kFixed ? kSections*(3 * kOrder + 1) : 1> local_words{};
  std::array<std::int64_t, kFixed ? (2 * kSections + 1) * kOrder : 1> local_history{};
  const std::int64_t* coef = merged_.data();
  std::int64_t* hist = history_.data();
  if constexpr (kFixed) {
    std::copy(merged_.begin(), merged_.end(), local_words.begin());
    std::copy(history_.begin(), history_.end(), local_history.begin());
    coef = local_words.data();
    hist = local_history.data();
  }

  std::int64_t u = 0;  // the section's input: x << s, then each section's y_ext
  bool saturated = false;
  const auto section = [&](int k) __attribute__((always_inline)) {
    const std::int64_t* const cb = coef + k * words;  // c_b[0..M]
    const std::int64_t* const ca = cb + m;            // c_a[1..M] at ca[1..M]
    const std::int64_t* const ce = cb + 2 * m;        // E[1..M] 2^L at ce[1..M]
    std::int64_t* const uh = hist + k * m;            // u[n-1..n-M]
    const std::int64_t* const wh = uh + m;            // w[n-1..n-M]
    std::int64_t* const eh = hist + (sections + 1 + k) * m;
    // The older terms first, so that the newest (u[n], w[n-1], e[n-1]) end the dependency chain.
    std::int64_t older = preload;
    for (int j = m; j >= 2; --j) older += cb[j] * uh[j - 1] + ca[j] * wh[j - 1] + ce[j] * eh[j - 1];
    const std::int64_t sum = older + cb[1] * uh[0] + ca[1] * wh[0] + ce[1] * eh[0] + cb[0] * u;
    const std::int64_t shifted = sum >> total_shift;  // acc >>> F, arithmetic (C++20)
    const std::int64_t y_ext = std::clamp(shifted, lim.ext_min, lim.ext_max);
    const std::uint64_t span = k + 1 < sections ? lim.span_mid : lim.span_last;
    saturated |= static_cast<std::uint64_t>(shifted - lim.ext_min) > span;
    push_line<kOrder>(eh, m, ((sum >> lim.split) & lim.mask_f) - lim.half_f);
    push_line<kOrder>(uh, m, u);
    u = y_ext;
  };

  for (std::size_t i = 0; i < n; ++i) {
    u = std::int64_t{in[i]} * (std::int64_t{1} << lim.s);
    saturated = false;
    if constexpr (kFixed) {
      // Unrolled, so that every index is a constant and the arrays can live in registers.
      [&]<int... k>(std::integer_sequence<int, k...>) { (section(k), ...); }
      (std::make_integer_sequence<int, kSections>{});
    } else {
      for (int k = 0; k < sections; ++k) section(k);
    }
    push_line<kOrder>(hist + sections * m, m, u);
    out[i] = {static_cast<std::int32_t>(std::min((u + lim.half_s) >> lim.s, lim.out_max)),
              saturated};
  }

  if constexpr (kFixed) std::copy(local_history.begin(), local_history.end(), history_.begin());
}

void IirSampleModel::run_two_phase(const std::int32_t* in, SampleResult* out, std::size_t n) {
  const Limits lim(*this);
  const CoreConfig& c = config_;
  const int m = lim.m;
  const int sections = lim.sections;
  std::int64_t* const hist = history_.data();
  const std::uint64_t preload = std::uint64_t{1} << (lim.f - 1 + lim.split);
  // The P-bit two's complement value of a sum modulo 2^64: the sign bit of P to bit 63 and back.
  const auto wrap = [&lim](std::uint64_t p) {
    return static_cast<std::int64_t>(p << lim.wrap_shift) >> lim.wrap_shift;
  };
  // Exact products (D + s + C <= P <= 64), summed modulo 2^64 like iir_mac.h's mac().
  const auto product = [](std::int64_t word, std::int64_t operand) {
    return static_cast<std::uint64_t>(word * operand);
  };
  for (std::size_t i = 0; i < n; ++i) {
    std::int64_t u = std::int64_t{in[i]} * (std::int64_t{1} << lim.s);
    bool saturated = false;
    for (int k = 0; k < sections; ++k) {
      const std::int64_t* const words = c.rom.data() + k * c.terms();
      std::int64_t* const uh = hist + k * m;
      const std::int64_t* const wh = uh + m;
      std::int64_t* const eh = hist + (sections + 1 + k) * m;
      std::uint64_t lo = preload + product(words[c.lo_b(0)], u);
      std::uint64_t hi = product(words[c.hi_b(0)], u);
      for (int j = 1; j <= m; ++j) {
        lo += product(words[c.lo_b(j)], uh[j - 1]) + product(words[c.lo_a(j)], wh[j - 1]);
        hi += product(words[c.hi_b(j)], uh[j - 1]) + product(words[c.hi_a(j)], wh[j - 1]) +
              product(words[c.err(j)], eh[j - 1]);
      }
      const std::int64_t acc =
          wrap(static_cast<std::uint64_t>(wrap(lo) >> lim.split) + hi);  // arithmetic shift
      const std::int64_t shifted = acc >> lim.f;
      const std::int64_t y_ext = std::clamp(shifted, lim.ext_min, lim.ext_max);
      const std::uint64_t span = k + 1 < sections ? lim.span_mid : lim.span_last;
      saturated |= static_cast<std::uint64_t>(shifted - lim.ext_min) > span;
      push_line<0>(eh, m, (acc & lim.mask_f) - lim.half_f);
      push_line<0>(uh, m, u);
      u = y_ext;
    }
    push_line<0>(hist + sections * m, m, u);
    out[i] = {static_cast<std::int32_t>(std::min((u + lim.half_s) >> lim.s, lim.out_max)),
              saturated};
  }
}

void IirSampleModel::run_vector(const std::int32_t* in, SampleResult* out, std::size_t n) {
  vector::run(*plan_, history_.data(), in, out, n);
}

void IirSampleModel::run(const std::int32_t* in, SampleResult* out, std::size_t n) {
  // Below this many samples the vector kernel's pipeline fill and drain (2(K-1) steps each) cost
  // more than the scalar merged kernel, which continues from the same state bit for bit.
  constexpr std::size_t kVectorMinBlock = 64;
  switch (kernel_) {
    case SampleKernel::kVector:
    case SampleKernel::kVectorMerged:
      if (n < kVectorMinBlock && merged_run_ != nullptr) {
        (this->*merged_run_)(in, out, n);
      } else {
        run_vector(in, out, n);
      }
      break;
    case SampleKernel::kMerged:
      (this->*merged_run_)(in, out, n);
      break;
    default:
      run_two_phase(in, out, n);
      break;
  }
}

SampleResult IirSampleModel::step(std::int32_t sample) {
  if (sample < sample_min_ || sample > sample_max_) {
    throw std::out_of_range(fmt::format("IirSampleModel: sample {} outside [{}, {}]", sample,
                                        sample_min_, sample_max_));
  }
  SampleResult result;
  // One sample: the general merged kernel works on the members in place; a fixed one would copy
  // them in and out, the vector one fill and drain its pipeline.
  if (!merged_.empty()) {
    run_merged<0, 0>(&sample, &result, 1);
  } else {
    run(&sample, &result, 1);
  }
  return result;
}

void IirSampleModel::filter(std::span<const std::int32_t> in, std::span<SampleResult> out) {
  if (in.size() != out.size()) {
    throw std::invalid_argument(
        fmt::format("IirSampleModel::filter: {} inputs but {} outputs", in.size(), out.size()));
  }
  // One unsigned compare per sample, in groups of a fixed size that -O2 vectorises
  // (std::minmax_element is not vectorised: it cost 30 % of a block's time); the error path finds
  // the sample to name.
  const auto low = static_cast<std::uint32_t>(sample_min_);
  const std::uint32_t span = static_cast<std::uint32_t>(sample_max_) - low;
  const auto outside = [low, span](const std::int32_t* x, std::size_t n) {
    std::uint32_t any = 0;
    for (std::size_t i = 0; i < n; ++i) any |= (static_cast<std::uint32_t>(x[i]) - low > span);
    return any;
  };
  constexpr std::size_t kGroup = 32;
  std::uint32_t any = 0;
  std::size_t i = 0;
  for (; i + kGroup <= in.size(); i += kGroup) any |= outside(in.data() + i, kGroup);
  any |= outside(in.data() + i, in.size() - i);
  if (any != 0) {
    const auto [lo, hi] = std::minmax_element(in.begin(), in.end());
    const std::int32_t bad = *lo < sample_min_ ? *lo : *hi;
    throw std::out_of_range(
        fmt::format("IirSampleModel: sample {} outside [{}, {}]", bad, sample_min_, sample_max_));
  }
  run(in.data(), out.data(), in.size());
}

}  // namespace flange::model
