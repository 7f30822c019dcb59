// SPDX-License-Identifier: MIT
#include "iir_sample_vector.h"

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <vector>

#include "iir_sample_model.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define FLANGE_VECTOR_KERNEL 1
#include <immintrin.h>
#else
#define FLANGE_VECTOR_KERNEL 0
#endif

namespace flange::model::vector {

namespace {

// Word kinds in Plan::words, `lanes` values each: lo_b(i), lo_a(j), hi_b(i), hi_a(j), err(j).
int kind_lo_b(int, int i) { return i; }
int kind_lo_a(int m, int j) { return m + j; }
int kind_hi_b(int m, int i) { return 2 * m + 1 + i; }
int kind_hi_a(int m, int j) { return 3 * m + 1 + j; }
int kind_err(int m, int j) { return 4 * m + 1 + j; }

bool cpu_has_instructions() {
#if FLANGE_VECTOR_KERNEL
  static const bool has = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
                          __builtin_cpu_supports("avx512ifma");
  return has;
#else
  return false;
#endif
}

}  // namespace

bool supported(const CoreConfig& c) {
  // y_ext, the words of the last step's terms and r < 2^F are 32-bit operands of vpmuldq.
  return cpu_has_instructions() && c.num_channels == 1 && c.section_order <= 2 &&
         c.num_sections >= 2 && c.num_sections <= 8 && c.coef_frac_bits <= 31 &&
         c.sample_width + c.feedback_shift <= 32;
}

// Plan::words holds the ROM words of word t of every section side by side: the word kinds above
// are the ROM offsets (CoreConfig::lo_b .. err).
Plan make_plan(const CoreConfig& c) {
  Plan p;
  p.sections = c.num_sections;
  p.order = c.section_order;
  p.lanes = c.num_sections <= 4 ? 4 : 8;
  p.split = c.split_shift();
  p.frac = c.coef_frac_bits;
  p.shift = c.feedback_shift;
  p.half_f = std::int64_t{1} << (p.frac - 1);
  p.mask_f = (std::int64_t{1} << p.frac) - 1;
  const std::int64_t sample_max = (std::int64_t{1} << (c.sample_width - 1)) - 1;
  p.out_max = sample_max;
  p.ext_max = ((sample_max + 1) << p.shift) - 1;
  p.ext_min = -((sample_max + 1) << p.shift);
  p.half_s = p.shift > 0 ? std::int64_t{1} << (p.shift - 1) : 0;
  const int m = p.order;
  p.words.assign(static_cast<std::size_t>((5 * m + 2) * p.lanes), 0);
  for (int k = 0; k < c.num_sections; ++k) {
    const std::int64_t* w = c.rom.data() + k * c.terms();
    for (int t = 0; t < c.terms(); ++t) {
      p.words[static_cast<std::size_t>(t * p.lanes + k)] = w[t];
    }
  }
  return p;
}

#if FLANGE_VECTOR_KERNEL
// Everything from here to the dispatcher is compiled for AVX-512 (lambdas included); only run(),
// after the CPU check, enters it.
#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx512f,avx512vl,avx512ifma"))), \
                             apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx512f,avx512vl,avx512ifma")
// GCC 12's AVX-512 headers start some intrinsics from _mm512_undefined_epi32() and warn about it.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
#endif
#define FLANGE_TARGET __attribute__((always_inline))

namespace {

struct Ymm {
  using V = __m256i;
  using DwordMask = __mmask8;
  static constexpr int kLanes = 4;
  FLANGE_TARGET static V set1(std::int64_t v) { return _mm256_set1_epi64x(v); }
  FLANGE_TARGET static V load(const std::int64_t* p) {
    return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(p));
  }
  FLANGE_TARGET static void store(std::int64_t* p, V v) {
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(p), v);
  }
  FLANGE_TARGET static V madd(V acc, V a, V b) { return _mm256_madd52lo_epu64(acc, a, b); }
  FLANGE_TARGET static V add(V a, V b) { return _mm256_add_epi64(a, b); }
  FLANGE_TARGET static V band(V a, V b) { return _mm256_and_si256(a, b); }
  FLANGE_TARGET static V srav(V a, V n) { return _mm256_srav_epi64(a, n); }
  // Lane 0 from b's top lane, lane i from a's lane i - 1.
  FLANGE_TARGET static V shift_in(V a, V b) { return _mm256_alignr_epi64(a, b, 3); }
  // Lanes with y outside [lo, lo + span] (unsigned compare of y - lo).
  FLANGE_TARGET static __mmask8 outside(V y, V lo, V span) {
    return static_cast<__mmask8>(_mm256_cmpgt_epu64_mask(_mm256_sub_epi64(y, lo), span));
  }
  FLANGE_TARGET static V mul32(V a, V b) { return _mm256_mul_epi32(a, b); }
  // The two's complement value of bits 0..51.
  FLANGE_TARGET static V sext52(V a) { return _mm256_srai_epi64(_mm256_slli_epi64(a, 12), 12); }
  FLANGE_TARGET static V shl12(V a) { return _mm256_slli_epi64(a, 12); }
  FLANGE_TARGET static V widen32(const std::int32_t* p) {
    return _mm256_cvtepi32_epi64(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p)));
  }
  FLANGE_TARGET static __mmask8 nonzero8(const std::uint8_t* p) {
    std::uint32_t bytes;
    __builtin_memcpy(&bytes, p, 4);
    const __m256i v = _mm256_cvtepu8_epi64(_mm_cvtsi32_si128(static_cast<int>(bytes)));
    return static_cast<__mmask8>(_mm256_test_epi64_mask(v, v));
  }
  FLANGE_TARGET static __mmask8 gt(V a, V b) {
    return static_cast<__mmask8>(_mm256_cmpgt_epi64_mask(a, b));
  }
  FLANGE_TARGET static V min(V a, V b) { return _mm256_min_epi64(a, b); }
  FLANGE_TARGET static V mask_or(V a, __mmask8 k, V b) { return _mm256_mask_or_epi64(a, k, a, b); }
  FLANGE_TARGET static V clamp(V y, V lo, V hi) {
    return _mm256_min_epi64(_mm256_max_epi64(y, lo), hi);
  }
  FLANGE_TARGET static V blend(__mmask8 k, V a, V b) { return _mm256_mask_blend_epi64(k, a, b); }
  FLANGE_TARGET static void store_dword(std::uintptr_t at, DwordMask k, V v) {
    _mm256_mask_storeu_epi32(reinterpret_cast<void*>(at), k, v);
  }
  FLANGE_TARGET static V max(V a, V b) { return _mm256_max_epi64(a, b); }
  FLANGE_TARGET static V sllv(V a, V n) { return _mm256_sllv_epi64(a, n); }
};

struct Zmm {
  using V = __m512i;
  using DwordMask = __mmask16;
  static constexpr int kLanes = 8;
  FLANGE_TARGET static V set1(std::int64_t v) { return _mm512_set1_epi64(v); }
  FLANGE_TARGET static V load(const std::int64_t* p) { return _mm512_loadu_si512(p); }
  FLANGE_TARGET static void store(std::int64_t* p, V v) { _mm512_storeu_si512(p, v); }
  FLANGE_TARGET static V madd(V acc, V a, V b) { return _mm512_madd52lo_epu64(acc, a, b); }
  FLANGE_TARGET static V add(V a, V b) { return _mm512_add_epi64(a, b); }
  FLANGE_TARGET static V band(V a, V b) { return _mm512_and_si512(a, b); }
  FLANGE_TARGET static V srav(V a, V n) { return _mm512_srav_epi64(a, n); }
  FLANGE_TARGET static V shift_in(V a, V b) { return _mm512_alignr_epi64(a, b, 7); }
  // Lanes with y outside [lo, lo + span] (unsigned compare of y - lo).
  FLANGE_TARGET static __mmask8 outside(V y, V lo, V span) {
    return static_cast<__mmask8>(_mm512_cmpgt_epu64_mask(_mm512_sub_epi64(y, lo), span));
  }
  FLANGE_TARGET static V mul32(V a, V b) { return _mm512_mul_epi32(a, b); }
  // The two's complement value of bits 0..51.
  FLANGE_TARGET static V sext52(V a) { return _mm512_srai_epi64(_mm512_slli_epi64(a, 12), 12); }
  FLANGE_TARGET static V shl12(V a) { return _mm512_slli_epi64(a, 12); }
  FLANGE_TARGET static V widen32(const std::int32_t* p) {
    return _mm512_cvtepi32_epi64(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(p)));
  }
  FLANGE_TARGET static __mmask8 nonzero8(const std::uint8_t* p) {
    std::uint64_t bytes;
    __builtin_memcpy(&bytes, p, 8);
    const __m512i v = _mm512_cvtepu8_epi64(_mm_cvtsi64_si128(static_cast<long long>(bytes)));
    return static_cast<__mmask8>(_mm512_test_epi64_mask(v, v));
  }
  FLANGE_TARGET static __mmask8 gt(V a, V b) {
    return static_cast<__mmask8>(_mm512_cmpgt_epi64_mask(a, b));
  }
  FLANGE_TARGET static V min(V a, V b) { return _mm512_min_epi64(a, b); }
  FLANGE_TARGET static V mask_or(V a, __mmask8 k, V b) { return _mm512_mask_or_epi64(a, k, a, b); }
  FLANGE_TARGET static V clamp(V y, V lo, V hi) {
    return _mm512_min_epi64(_mm512_max_epi64(y, lo), hi);
  }
  FLANGE_TARGET static V blend(__mmask8 k, V a, V b) { return _mm512_mask_blend_epi64(k, a, b); }
  FLANGE_TARGET static void store_dword(std::uintptr_t at, DwordMask k, V v) {
    _mm512_mask_storeu_epi32(reinterpret_cast<void*>(at), k, v);
  }
  FLANGE_TARGET static V max(V a, V b) { return _mm512_max_epi64(a, b); }
  FLANGE_TARGET static V sllv(V a, V n) { return _mm512_sllv_epi64(a, n); }
};

// A lane's words and the kernel's constants, as vectors.
template <class T, int m>
struct Words {
  using V = typename T::V;
  V wb[m + 1], hb[m + 1];             // W_b[i], H_b[i], i = 0..M
  V wa[m + 1], ha[m + 1], ee[m + 1];  // W_a[j], H_a[j], E[j], j = 1..M ([0] unused)
  V pre_lo, shift_lo, shift_acc, mask_f, ext_min, ext_max, ext_span;  // shift_lo = L + 12
};

// Each lane's history: u (its input), w (its y_ext), r (its errors + 2^(F-1)), newest first; and
// the y_ext of the last two steps (lane k's feeds lane k + 1 two steps later).
template <class T>
struct State {
  using V = typename T::V;
  V u1, u2, w1, w2, r1, r2, y1, y2;
};

// The smallest and largest unclipped y_ext of the steps taken without the clip test.
template <class T>
struct Seen {
  typename T::V low, high;
};

// One step: every active lane computes its section on its sample. Returns the lanes that clipped
// (kCheck). Without kCheck y_ext is not clipped, only recorded in `seen`: the caller redoes the
// steps with the test if it falls outside the range.
template <class T, int m, bool kMasked, bool kCheck = true>
FLANGE_TARGET inline __mmask8 lane_step(const Words<T, m>& c, State<T>& s, const std::int64_t* x_at,
                                        __mmask8 active, Seen<T>* seen = nullptr) {
  using V = typename T::V;
  const V zero = T::set1(0);
  const V u0 = T::shift_in(s.y2, T::load(x_at));
  // The H and E terms of what the last step made (w[n-1], r[n-1]) are exact 32 x 32-bit products
  // added to exact int64 sums. Everything else is summed modulo 2^52 by multiply-adds, oldest first
  // and u0 (step t-2's y_ext, shifted in) late, and sign-extended from bit 51. The loop-carried
  // paths: y[t-1] -> y[t] a multiply-add (or a product and an add), two shifts, an add and >>> F
  // (8 cycles); acc -> acc the mask, a product and three adds (9 cycles).
  V lo_pre = c.pre_lo, hi_pre = zero;
  if constexpr (m == 2) {
    lo_pre = T::madd(T::madd(lo_pre, c.wb[2], s.u2), c.wb[1], s.u1);
    hi_pre = T::madd(T::madd(hi_pre, c.hb[2], s.u2), c.hb[1], s.u1);
    lo_pre = T::madd(lo_pre, c.wa[2], s.w2);
    hi_pre = T::madd(hi_pre, c.ee[2], s.r2);
    // Two chains, added: a chain of five multiply-adds (4 cycles each) would end after y[t-1]'s.
    hi_pre = T::add(hi_pre, T::madd(T::madd(zero, c.ha[2], s.w2), c.hb[0], u0));
  } else {
    lo_pre = T::madd(lo_pre, c.wb[1], s.u1);
    hi_pre = T::madd(hi_pre, c.hb[1], s.u1);
    hi_pre = T::madd(hi_pre, c.hb[0], u0);
  }
  lo_pre = T::madd(lo_pre, c.wb[0], u0);
  // lo's last term too is a multiply-add (4 cycles, against 5 for the exact product and 1 for its
  // add); lo >>> L then comes from bits 0..51 moved to the top and shifted down by L + 12.
  const V lo = T::shl12(T::madd(lo_pre, c.wa[1], s.w1));
  V hi = T::add(T::add(T::sext52(hi_pre), T::mul32(c.ee[1], s.r1)), T::mul32(c.ha[1], s.w1));
  // Keep hi summed on its own: then the add after lo >>> L is the only one on the path.
  asm("" : "+v"(hi));
  const V acc = T::add(hi, T::srav(lo, c.shift_lo));
  V y = T::srav(acc, c.shift_acc);
  const V r0 = T::band(acc, c.mask_f);
  __mmask8 clipped = 0;
  if constexpr (kCheck) {
    clipped = static_cast<__mmask8>(T::outside(y, c.ext_min, c.ext_span) & active);
    if (__builtin_expect(clipped != 0, 0)) y = T::clamp(y, c.ext_min, c.ext_max);
  } else {
    seen->low = T::min(seen->low, y);
    seen->high = T::max(seen->high, y);
  }
  if constexpr (kMasked) {
    if constexpr (m == 2) {
      s.u2 = T::blend(active, s.u2, s.u1);
      s.w2 = T::blend(active, s.w2, s.w1);
      s.r2 = T::blend(active, s.r2, s.r1);
    }
    s.u1 = T::blend(active, s.u1, u0);
    s.w1 = T::blend(active, s.w1, y);
    s.r1 = T::blend(active, s.r1, r0);
  } else {
    s.u2 = s.u1;
    s.w2 = s.w1;
    s.r2 = s.r1;
    s.u1 = u0;
    s.w1 = y;
    s.r1 = r0;
  }
  s.y2 = s.y1;
  s.y1 = y;
  return clipped;
}

// The ring of per-sample clip flags (sample i at [i mod kRing]): more than the samples in flight.
constexpr std::size_t kChunk = 512;
constexpr std::size_t kRing = 2 * kChunk;

// Marks the samples whose sections clipped at step t (section k works on sample t - 2k). Inline
// and without calls: a call in the loop would make the compiler keep the lanes' state in memory.
// `dirty_until` is above every sample marked so far (finish_samples skips the ring above it).
FLANGE_TARGET inline void record_clips(std::uint8_t* ring, std::size_t& dirty_until,
                                       unsigned clipped, std::size_t t) {
  for (int k = 0; clipped >> k; ++k) {
    if ((clipped >> k) & 1) ring[(t - static_cast<std::size_t>(2 * k)) % kRing] = 1;
  }
  dirty_until = std::max(dirty_until, t + 1);
}

// Samples [first, end): the last section's y_ext (y[i - first]) rounded half up to D bits and
// clipped, saturated if that clipped or a section did (ring); the ring's flags are cleared.
template <class T>
FLANGE_TARGET inline void finish_samples(const Plan& p, const std::int32_t* y, std::uint8_t* ring,
                                         bool ring_clean, SampleResult* out, std::size_t first,
                                         std::size_t end) {
  using V = typename T::V;
  static_assert(sizeof(SampleResult) == 8 && offsetof(SampleResult, saturated) == 4);
  const V half = T::set1(p.half_s), shift = T::set1(p.shift), top = T::set1(p.out_max);
  const V low32 = T::set1(0xffffffff), flag = T::set1(std::int64_t{1} << 32);
  std::size_t i = first;
  // Whole vectors that do not wrap around the ring; one by one only the samples before the wrap
  // (with 2(K-1) not a multiple of the lanes every other chunk crosses it: the rest of such a
  // chunk went one by one before) and at the end.
  const auto scalar = [&](std::size_t at) __attribute__((always_inline)) {
    const std::int64_t rounded = (std::int64_t{y[at - first]} + p.half_s) >> p.shift;
    const bool clip = rounded > p.out_max;
    out[at] = {static_cast<std::int32_t>(clip ? p.out_max : rounded),
               clip || ring[at % kRing] != 0};
    ring[at % kRing] = 0;
  };
  while (i + T::kLanes <= end) {
    if (i % kRing + T::kLanes > kRing) {
      for (; i % kRing != 0; ++i) scalar(i);
      continue;
    }
    const V rounded = T::srav(T::add(T::widen32(y + (i - first)), half), shift);
    auto flagged = T::gt(rounded, top);
    if (!ring_clean) {
      flagged = static_cast<__mmask8>(flagged | T::nonzero8(ring + i % kRing));
      std::fill(ring + i % kRing, ring + i % kRing + T::kLanes, std::uint8_t{0});
    }
    T::store(reinterpret_cast<std::int64_t*>(out + i),
             T::mask_or(T::band(T::min(rounded, top), low32), flagged, flag));
    i += T::kLanes;
  }
  for (; i < end; ++i) scalar(i);
}

// The kernel for `lanes` = T::kLanes and M = kOrder.
template <class T, int kOrder>
void run_lanes(const Plan& p, std::int64_t* history, const std::int32_t* in, SampleResult* out,
               std::size_t n) {
  using V = typename T::V;
  constexpr int m = kOrder;
  constexpr int kLanes = T::kLanes;
  const int sections = p.sections;
  Words<T, m> c;
  const auto word = [&](int kind) { return T::load(p.words.data() + kind * kLanes); };
  for (int i = 0; i <= m; ++i) {
    c.wb[i] = word(kind_lo_b(m, i));
    c.hb[i] = word(kind_hi_b(m, i));
  }
  c.wa[0] = c.ha[0] = c.ee[0] = T::set1(0);
  for (int j = 1; j <= m; ++j) {
    c.wa[j] = word(kind_lo_a(m, j));
    c.ha[j] = word(kind_hi_a(m, j));
    c.ee[j] = word(kind_err(m, j));
  }
  // The error history is kept as r = acc mod 2^F = e + 2^(F-1): sum E[j] e[n-j] = sum E[j] r[n-j]
  // - 2^(F-1) sum E[j], and that constant goes into lo's preload, times 2^L, per lane:
  // 2^(F-1+L) - 2^(F-1) (E[1] + .. + E[M]) 2^L.
  alignas(64) std::int64_t buf[kLanes];
  for (int k = 0; k < kLanes; ++k) {
    std::int64_t sum_e = 0;
    for (int j = 1; j <= m; ++j) {
      sum_e += p.words[static_cast<std::size_t>(kind_err(m, j) * kLanes + k)];
    }
    buf[k] = k < sections ? (p.half_f - p.half_f * sum_e) * (std::int64_t{1} << p.split) : 0;
  }
  c.pre_lo = T::load(buf);
  c.shift_lo = T::set1(p.split + 12);
  c.shift_acc = T::set1(p.frac);
  c.mask_f = T::set1(p.mask_f);
  c.ext_min = T::set1(p.ext_min);
  c.ext_max = T::set1(p.ext_max);
  c.ext_span = T::set1(p.ext_max - p.ext_min);
  const auto lane_mask = static_cast<__mmask8>((1u << sections) - 1);

  const auto line = [&](int l, int age) -> std::int64_t& {
    return history[static_cast<std::size_t>(l * m + age - 1)];
  };
  const auto gather = [&](int first_line, int age, std::int64_t plus) {
    for (int k = 0; k < kLanes; ++k) buf[k] = k < sections ? line(first_line + k, age) + plus : 0;
    return T::load(buf);
  };
  State<T> s;
  s.u1 = gather(0, 1, 0);
  s.w1 = gather(1, 1, 0);
  s.r1 = gather(sections + 1, 1, p.half_f);
  s.u2 = m == 2 ? gather(0, 2, 0) : T::set1(0);
  s.w2 = m == 2 ? gather(1, 2, 0) : T::set1(0);
  s.r2 = m == 2 ? gather(sections + 1, 2, p.half_f) : T::set1(0);
  s.y1 = s.y2 = T::set1(0);

  const int last = sections - 1;
  const std::size_t skew = static_cast<std::size_t>(2 * last);
  const std::size_t steps = n + skew;
  // The inputs x << s of a chunk of steps, widened: x[c0 + j] at [kLanes - 1 + j], the top lane of
  // the load at [j] (only the top lane is used).
  alignas(64) std::int64_t xs[kChunk + kLanes] = {};
  // The last section's y_ext of the samples a chunk finishes, [c0 - skew, c1 - skew), one per
  // step: a masked store of lane K - 1's low dword alone, at an address 2(K - 1) dwords early
  // (masked-out lanes never touch memory). finish_samples then writes them to out.
  alignas(64) std::int32_t ys[kChunk];
  std::uint8_t ring[kRing] = {};
  std::size_t dirty_until = 0;  // every sample marked in the ring is below this
  const auto y_mask = static_cast<typename T::DwordMask>(1u << (2 * last));
  const std::uintptr_t y_base =
      reinterpret_cast<std::uintptr_t>(ys) - 8 * static_cast<std::uintptr_t>(last);
  const auto masked_step = [&](std::size_t t, std::size_t c0) __attribute__((always_inline)) {
    unsigned active = 0;
    for (int k = 0; k < sections; ++k) {
      const auto lag = static_cast<std::size_t>(2 * k);
      if (t >= lag && t - lag < n) active |= 1u << k;
    }
    const __mmask8 clipped =
        lane_step<T, m, true>(c, s, xs + (t - c0), static_cast<__mmask8>(active));
    if (clipped) record_clips(ring, dirty_until, clipped, t);
    if (active >> last) T::store_dword(y_base + 4 * (t - c0), y_mask, s.y1);
  };
  const V shift_in = T::set1(p.shift);
  for (std::size_t c0 = 0; c0 < steps; c0 += kChunk) {
    const std::size_t c1 = std::min(steps, c0 + kChunk);
    // This chunk's inputs x << s, widened.
    const std::size_t inputs_end = std::max(c0, std::min(c1, n));
    std::size_t t = c0;
    for (; t + T::kLanes <= inputs_end; t += T::kLanes) {
      T::store(xs + kLanes - 1 + (t - c0), T::sllv(T::widen32(in + t), shift_in));
    }
    for (; t < inputs_end; ++t) xs[kLanes - 1 + (t - c0)] = std::int64_t{in[t]} << p.shift;
    std::fill(xs + kLanes - 1 + (inputs_end - c0), xs + kLanes - 1 + (c1 - c0), 0);

    t = c0;
    for (; t < std::min(c1, skew); ++t) masked_step(t, c0);
    // Every lane active: first without the clip test, tracking y_ext's range; if some y_ext left
    // it (a clip, rare for a useful filter), back to the state before and again with the test.
    const std::size_t full_begin = t, full_end = std::max(t, std::min(c1, n));
    const State<T> before = s;
    Seen<T> seen{T::set1(p.ext_max), T::set1(p.ext_min)};
    for (; t + 1 < full_end; t += 2) {  // two steps a turn: the history moves by renaming
      lane_step<T, m, false, false>(c, s, xs + (t - c0), lane_mask, &seen);
      T::store_dword(y_base + 4 * (t - c0), y_mask, s.y1);
      lane_step<T, m, false, false>(c, s, xs + (t + 1 - c0), lane_mask, &seen);
      T::store_dword(y_base + 4 * (t + 1 - c0), y_mask, s.y1);
    }
    if (t < full_end) {
      lane_step<T, m, false, false>(c, s, xs + (t - c0), lane_mask, &seen);
      T::store_dword(y_base + 4 * (t - c0), y_mask, s.y1);
      ++t;
    }
    if (T::gt(c.ext_min, seen.low) | T::gt(seen.high, c.ext_max)) {
      s = before;
      for (t = full_begin; t < full_end; ++t) {
        const __mmask8 clipped = lane_step<T, m, false>(c, s, xs + (t - c0), lane_mask);
        if (clipped) record_clips(ring, dirty_until, clipped, t);
        T::store_dword(y_base + 4 * (t - c0), y_mask, s.y1);
      }
    }
    for (; t < c1; ++t) masked_step(t, c0);
    // The samples this chunk finished; ys[j] is sample c0 + j - skew.
    const std::size_t first = std::max(c0, skew), end = std::max(c1, skew);
    finish_samples<T>(p, ys + (first - c0), ring, first - skew >= dirty_until, out, first - skew,
                      end - skew);
  }

  // Back to the load registers: line k's words from lane k's input history, line K from the last
  // lane's output history, the errors less 2^(F-1).
  const auto scatter = [&](typename T::V v, int first_line, int age, std::int64_t minus) {
    T::store(buf, v);
    for (int k = 0; k < sections; ++k) line(first_line + k, age) = buf[k] - minus;
  };
  for (int age = 1; age <= m; ++age) {
    scatter(age == 1 ? s.u1 : s.u2, 0, age, 0);
    scatter(age == 1 ? s.r1 : s.r2, sections + 1, age, p.half_f);
    T::store(buf, age == 1 ? s.w1 : s.w2);
    line(sections, age) = buf[last];
  }
}

}  // namespace

#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif

void run(const Plan& p, std::int64_t* history, const std::int32_t* in, SampleResult* out,
         std::size_t n) {
  if (!cpu_has_instructions()) throw std::logic_error("vector kernel: no AVX-512 IFMA");
  if (p.lanes == 4) {
    if (p.order == 2) return run_lanes<Ymm, 2>(p, history, in, out, n);
    return run_lanes<Ymm, 1>(p, history, in, out, n);
  }
  if (p.order == 2) return run_lanes<Zmm, 2>(p, history, in, out, n);
  return run_lanes<Zmm, 1>(p, history, in, out, n);
}

#else

void run(const Plan&, std::int64_t*, const std::int32_t*, SampleResult*, std::size_t) {
  throw std::logic_error("vector kernel: not built for this architecture");
}

#endif

}  // namespace flange::model::vector
