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
std::size_t lane_word(const Plan& p, int kind, int lane) {
  return static_cast<std::size_t>(kind * p.lanes + lane);
}

bool cpu_has_instructions(Sums sums) {
#if FLANGE_VECTOR_KERNEL
  static const bool base = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl");
  static const bool ifma = base && __builtin_cpu_supports("avx512ifma");
  static const bool dq = base && __builtin_cpu_supports("avx512dq");
  return sums == Sums::kSplit ? ifma : dq;
#else
  (void)sums;
  return false;
#endif
}

__extension__ typedef unsigned __int128 u128;

// The largest magnitudes of one section's sums of biased values (signals below 2^(D+s), r below
// 2^F), per word group.
struct BiasedSums {
  u128 w = 0, h = 0, e = 0;  // sum |W|, sum |H|, sum |E|
  u128 signal = 0, error = 0;
};

BiasedSums biased_sums(const CoreConfig& c, int k) {
  const auto magnitude = [](std::int64_t v) { return static_cast<u128>(v < 0 ? -v : v); };
  const int m = c.section_order;
  const std::int64_t* w = c.rom.data() + k * c.terms();
  BiasedSums b;
  b.signal = u128{1} << (c.sample_width + c.feedback_shift);
  b.error = u128{1} << c.coef_frac_bits;
  for (int i = 0; i <= m; ++i) {
    b.w += magnitude(w[c.lo_b(i)]);
    b.h += magnitude(w[c.hi_b(i)]);
  }
  for (int j = 1; j <= m; ++j) {
    b.w += magnitude(w[c.lo_a(j)]);
    b.h += magnitude(w[c.hi_a(j)]);
    b.e += magnitude(w[c.err(j)]);
  }
  return b;
}

// The split sums stay exact: the older hi terms, summed modulo 2^52, within 2^51; lo with its
// preload (which holds the biases' constants times 2^L) within 2^62.
bool split_sums_fit(const CoreConfig& c) {
  const int split = c.split_shift();
  for (int k = 0; k < c.num_sections; ++k) {
    const BiasedSums b = biased_sums(c, k);
    const u128 hi = b.h * b.signal + b.e * b.error;
    const u128 g = b.signal * b.error + b.h * b.signal + b.e * b.error;
    const u128 lo = (b.error << split) + b.w * b.signal * 2 + (g << split);
    if (hi >= (u128{1} << 51) || lo >= (u128{1} << 62)) return false;
  }
  return true;
}

// The merged sums (lo + 2^L hi of the split ones: c = H 2^L + W, E 2^L) with their preload within
// 2^62.
bool merged_sums_fit(const CoreConfig& c) {
  const int split = c.split_shift();
  for (int k = 0; k < c.num_sections; ++k) {
    const BiasedSums b = biased_sums(c, k);
    const u128 coefficients = b.w + (b.h << split);
    const u128 g = b.signal * b.error + b.h * b.signal + b.e * b.error;
    const u128 sum = (b.error << split) + coefficients * b.signal * 2 + (g << split) +
                     ((b.e * b.error) << split);
    if (sum >= (u128{1} << 62)) return false;
  }
  return true;
}

}  // namespace

bool supported(const CoreConfig& c, Sums sums) {
  // Every signal is biased to be non-negative: y_ext + 2^(D-1+s) is below 2^(D+s), a 32-bit operand
  // (vpmuldq, and the dword the last section's y_ext is stored in), so D + s <= 31. Split sums:
  // lo words below 2^L and hi words below 2^(C-1) keep their products with it below 2^52, exact
  // in a multiply-add. Merged sums: 64-bit products (vpmullq), exact within the sums' bound.
  const int signal_bits = c.sample_width + c.feedback_shift;
  const bool shape = c.num_channels == 1 && c.section_order <= 2 && c.num_sections >= 2 &&
                     c.num_sections <= 8 && c.coef_frac_bits <= 31 && signal_bits <= 31;
  if (!cpu_has_instructions(sums) || !shape) return false;
  if (sums == Sums::kMerged) return merged_sums_fit(c);
  return c.split_shift() + signal_bits <= 52 && c.coef_width - 1 + signal_bits <= 52 &&
         split_sums_fit(c);
}

bool merged_preferred() {
#if FLANGE_VECTOR_KERNEL
  // AMD's AVX-512 cores (Zen 4 on) multiply 64 x 64 bits in one micro-op of 3 cycles; Intel's take
  // three of 15, which makes the split sums' 52-bit multiply-adds the faster kernel there.
  static const bool amd = __builtin_cpu_is("amd");
  return amd;
#else
  return false;
#endif
}

// Plan::words holds the ROM words of word t of every section side by side: the word kinds above
// are the ROM offsets (CoreConfig::lo_b .. err).
Plan make_plan(const CoreConfig& c, Sums sums) {
  Plan p;
  p.sums = sums;
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
  p.bias = (sample_max + 1) << p.shift;
  const int m = p.order;
  p.words.assign(static_cast<std::size_t>((5 * m + 2) * p.lanes), 0);
  for (int k = 0; k < c.num_sections; ++k) {
    const std::int64_t* w = c.rom.data() + k * c.terms();
    for (int t = 0; t < c.terms(); ++t) {
      p.words[static_cast<std::size_t>(t * p.lanes + k)] = w[t];
    }
    p.signed_ha1 = p.signed_ha1 || w[c.hi_a(1)] < 0;
  }
  return p;
}

#if FLANGE_VECTOR_KERNEL
// Everything from here to the dispatcher is compiled for AVX-512 (lambdas included); only run(),
// after the CPU check, enters it.
#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx512f,avx512vl,avx512ifma,avx512dq"))), \
                             apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx512f,avx512vl,avx512ifma,avx512dq")
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
  FLANGE_TARGET static V bor(V a, V b) { return _mm256_or_si256(a, b); }
  FLANGE_TARGET static bool any_common(V a, V b) { return _mm256_test_epi64_mask(a, b) != 0; }
  FLANGE_TARGET static V srav(V a, V n) { return _mm256_srav_epi64(a, n); }
  // Lane 0 from b's top lane, lane i from a's lane i - 1.
  FLANGE_TARGET static V shift_in(V a, V b) { return _mm256_alignr_epi64(a, b, 3); }
  // Lanes with y outside [0, top] (unsigned compare).
  FLANGE_TARGET static __mmask8 outside(V y, V top) {
    return static_cast<__mmask8>(_mm256_cmpgt_epu64_mask(y, top));
  }
  FLANGE_TARGET static V mul32(V a, V b) { return _mm256_mul_epi32(a, b); }
  FLANGE_TARGET static V mul64(V a, V b) { return _mm256_mullo_epi64(a, b); }
  // The two's complement value of bits 0..51.
  FLANGE_TARGET static V sext52(V a) { return _mm256_srai_epi64(_mm256_slli_epi64(a, 12), 12); }
  // (a ^ b) & c in one instruction.
  FLANGE_TARGET static V xor_and(V a, V b, V c) { return _mm256_ternarylogic_epi64(a, b, c, 0x28); }
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
  FLANGE_TARGET static V bor(V a, V b) { return _mm512_or_si512(a, b); }
  FLANGE_TARGET static bool any_common(V a, V b) { return _mm512_test_epi64_mask(a, b) != 0; }
  FLANGE_TARGET static V srav(V a, V n) { return _mm512_srav_epi64(a, n); }
  FLANGE_TARGET static V shift_in(V a, V b) { return _mm512_alignr_epi64(a, b, 7); }
  // Lanes with y outside [0, top] (unsigned compare).
  FLANGE_TARGET static __mmask8 outside(V y, V top) {
    return static_cast<__mmask8>(_mm512_cmpgt_epu64_mask(y, top));
  }
  FLANGE_TARGET static V mul32(V a, V b) { return _mm512_mul_epi32(a, b); }
  FLANGE_TARGET static V mul64(V a, V b) { return _mm512_mullo_epi64(a, b); }
  // The two's complement value of bits 0..51.
  FLANGE_TARGET static V sext52(V a) { return _mm512_srai_epi64(_mm512_slli_epi64(a, 12), 12); }
  // (a ^ b) & c in one instruction.
  FLANGE_TARGET static V xor_and(V a, V b, V c) { return _mm512_ternarylogic_epi64(a, b, c, 0x28); }
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
  FLANGE_TARGET static V sllv(V a, V n) { return _mm512_sllv_epi64(a, n); }
};

// A lane's words and the kernel's constants, as vectors. Merged sums: wb and wa hold
// c = H 2^L + W, hb and ha are unused, r is kept times 2^L (mask_f and flip too), and shift_acc is
// L + F.
template <class T, int m>
struct Words {
  using V = typename T::V;
  V wb[m + 1], hb[m + 1];             // W_b[i], H_b[i], i = 0..M
  V wa[m + 1], ha[m + 1], ee[m + 1];  // W_a[j], H_a[j], E[j] (negated where r is), j = 1..M
  V pre_lo, shift_lo, shift_acc, mask_f, flip, ext_max;  // flip: mask_f where r is kept negated
};

// Each lane's history, every value biased to be non-negative: u and w (its input and its y_ext)
// plus Y = 2^(D-1+s); r (its error + 2^(F-1), or 2^F - 1 less that where E[1] < 0: `flip`); newest
// first; and the biased y_ext of the last two steps (lane k's feeds lane k + 1 two steps later).
template <class T>
struct State {
  using V = typename T::V;
  V u1, u2, w1, w2, r1, r2, y1, y2;
};

// The bits of every unclipped biased y_ext of the steps taken without the clip test, or-ed: with
// 2Y = 2^(D+s), some y_ext left the range if a bit from D + s up is set (a negative one sets
// them all).
template <class T>
struct Seen {
  typename T::V bits;
};

// The split sums' acc (biased: acc + Y 2^F) of every lane's step.
template <class T, int m, bool kSignedHa1>
FLANGE_TARGET inline typename T::V split_sum(const Words<T, m>& c, const State<T>& s,
                                             typename T::V u0) {
  using V = typename T::V;
  const V zero = T::set1(0);
  // The terms of older values are summed modulo 2^52 by multiply-adds (signed words), oldest first
  // and u0 (step t-2's y_ext, shifted in) late, and sign-extended from bit 51. The terms of what
  // the last step made (w[n-1], r[n-1]) are exact products of non-negative operands below 2^52,
  // added to exact int64 sums, lo's included, so no sign extension is on the loop-carried path:
  // acc -> >>> F -> W_a[1] w multiply-add -> >>> L -> add -> acc (7 cycles); acc -> >>> F or the
  // r mask -> H_a[1] w or |E[1]| r multiply-add -> two adds -> acc (7 cycles).
  V lo_pre = c.pre_lo, hi_pre = zero;
  if constexpr (m == 2) {
    lo_pre = T::madd(T::madd(lo_pre, c.wb[2], s.u2), c.wb[1], s.u1);
    hi_pre = T::madd(T::madd(hi_pre, c.hb[2], s.u2), c.hb[1], s.u1);
    lo_pre = T::madd(lo_pre, c.wa[2], s.w2);
    // Two chains, added: a chain of four multiply-adds (4 cycles each) would end too late.
    hi_pre = T::add(T::madd(hi_pre, c.ee[2], s.r2), T::madd(zero, c.ha[2], s.w2));
  } else {
    lo_pre = T::madd(lo_pre, c.wb[1], s.u1);
    hi_pre = T::madd(hi_pre, c.hb[1], s.u1);
  }
  // u0 arrives a step before w[n-1] and r[n-1]: its terms start the chains that theirs end. H_b[0]
  // may be negative, so its product is a signed vpmuldq (exact, unlike a multiply-add of it).
  const V lo = T::madd(T::madd(lo_pre, c.wb[0], u0), c.wa[1], s.w1);
  const V hi_r = T::madd(T::mul32(c.hb[0], u0), c.ee[1], s.r1);
  V hi_w;
  if constexpr (kSignedHa1) {
    hi_w = T::add(T::sext52(hi_pre), T::mul32(c.ha[1], s.w1));
  } else {
    hi_w = T::madd(T::sext52(hi_pre), c.ha[1], s.w1);
  }
  V hi = T::add(hi_w, hi_r);
  // Keep hi summed on its own: then the add after lo >>> L is the only one on the path.
  asm("" : "+v"(hi));
  return T::add(hi, T::srav(lo, c.shift_lo));
}

// The merged sum (biased: sum + Y 2^(L+F)) of every lane's step: one exact 64-bit product per
// term. Loop-carried: y -> c_a[1] w product -> two adds -> y; r the same. The older terms in a
// tree, u0's product added to them, as it arrives a step before w[n-1] and r[n-1].
template <class T, int m>
FLANGE_TARGET inline typename T::V merged_sum(const Words<T, m>& c, const State<T>& s,
                                              typename T::V u0) {
  using V = typename T::V;
  V older;
  if constexpr (m == 2) {
    older = T::add(T::add(c.pre_lo, T::mul64(c.wb[2], s.u2)), T::mul64(c.wb[1], s.u1));
    older = T::add(older, T::add(T::mul64(c.wa[2], s.w2), T::mul64(c.ee[2], s.r2)));
  } else {
    older = T::add(c.pre_lo, T::mul64(c.wb[1], s.u1));
  }
  const V newest = T::add(T::mul64(c.wa[1], s.w1), T::mul64(c.ee[1], s.r1));
  return T::add(T::add(older, T::mul64(c.wb[0], u0)), newest);
}

// One step: every active lane computes its section on its sample. Returns the lanes that clipped
// (kCheck). Without kCheck y_ext is not clipped, only recorded in `seen`: the caller redoes the
// steps with the test if it falls outside the range. kSignedHa1 (split sums): some lane's H_a[1]
// is negative, so its product with w[n-1] is a signed vpmuldq instead of a multiply-add.
template <class T, int m, Sums kSums, bool kSignedHa1, bool kMasked, bool kCheck = true>
FLANGE_TARGET inline __mmask8 lane_step(const Words<T, m>& c, State<T>& s, const std::int64_t* x_at,
                                        __mmask8 active, Seen<T>* seen = nullptr) {
  using V = typename T::V;
  const V zero = T::set1(0);
  const V u0 = T::shift_in(s.y2, T::load(x_at));
  V acc;
  if constexpr (kSums == Sums::kMerged) {
    acc = merged_sum(c, s, u0);
  } else {
    acc = split_sum<T, m, kSignedHa1>(c, s, u0);
  }
  V y = T::srav(acc, c.shift_acc);
  const V r0 = T::xor_and(acc, c.flip, c.mask_f);
  __mmask8 clipped = 0;
  if constexpr (kCheck) {
    clipped = static_cast<__mmask8>(T::outside(y, c.ext_max) & active);
    if (__builtin_expect(clipped != 0, 0)) y = T::clamp(y, zero, c.ext_max);
  } else {
    seen->bits = T::bor(seen->bits, y);
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
// Steps taken without the clip test before the range is checked: a part that left it is rerun.
constexpr std::size_t kPart = 64;

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

// Samples [first, end): the last section's y_ext (y[i - first], biased by Y) rounded half up to D
// bits and clipped, saturated if that clipped or a section did (ring); the ring's flags are
// cleared.
template <class T>
FLANGE_TARGET inline void finish_samples(const Plan& p, const std::int32_t* y, std::uint8_t* ring,
                                         bool ring_clean, SampleResult* out, std::size_t first,
                                         std::size_t end) {
  using V = typename T::V;
  static_assert(sizeof(SampleResult) == 8 && offsetof(SampleResult, saturated) == 4);
  const std::int64_t half_less_bias = p.half_s - p.bias;
  const V half = T::set1(half_less_bias), shift = T::set1(p.shift), top = T::set1(p.out_max);
  const V low32 = T::set1(0xffffffff), flag = T::set1(std::int64_t{1} << 32);
  std::size_t i = first;
  // Whole vectors that do not wrap around the ring; one by one only the samples before the wrap
  // (with 2(K-1) not a multiple of the lanes every other chunk crosses it: the rest of such a
  // chunk went one by one before) and at the end.
  const auto scalar = [&](std::size_t at) __attribute__((always_inline)) {
    const std::int64_t rounded = (std::int64_t{y[at - first]} + half_less_bias) >> p.shift;
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

// The lanes' words and the kernel's constants, lane k holding section k's. `flip` (all 0 on entry)
// gets per lane what r is xor-ed with: 2^F - 1 (times 2^L with merged sums) where r is kept
// negated, else 0.
template <class T, int m, Sums kSums>
FLANGE_TARGET inline void lane_words(const Plan& p, std::int64_t* flip, Words<T, m>& c) {
  constexpr int kLanes = T::kLanes;
  const int sections = p.sections;
  constexpr bool kMergedSums = kSums == Sums::kMerged;
  // Merged sums: r is kept times 2^L, and lo's words take their hi words: c = H 2^L + W.
  const int r_shift = kMergedSums ? p.split : 0;
  alignas(64) std::int64_t buf[kLanes];
  const auto word = [&](int kind) {
    for (int k = 0; k < kLanes; ++k) buf[k] = p.words[lane_word(p, kind, k)];
    return T::load(buf);
  };
  // A lo word, or with merged sums kMerged's word c = H 2^L + W (its hi word is then unused).
  const auto lo_word = [&](int lo_kind, int hi_kind) {
    for (int k = 0; k < kLanes; ++k) {
      buf[k] = p.words[lane_word(p, lo_kind, k)];
      if (kMergedSums) buf[k] += p.words[lane_word(p, hi_kind, k)] * (std::int64_t{1} << p.split);
    }
    return T::load(buf);
  };
  for (int i = 0; i <= m; ++i) {
    c.wb[i] = lo_word(kind_lo_b(m, i), kind_hi_b(m, i));
    c.hb[i] = word(kind_hi_b(m, i));
  }
  c.wa[0] = c.ha[0] = c.ee[0] = T::set1(0);
  for (int j = 1; j <= m; ++j) {
    c.wa[j] = lo_word(kind_lo_a(m, j), kind_hi_a(m, j));
    c.ha[j] = word(kind_hi_a(m, j));
  }
  // Per lane: whether r is kept negated (E[1] < 0, so that |E[1]| r is a product of non-negative
  // operands), the error words to match, and lo's preload (the merged sum's too: the same value).
  for (int k = 0; k < sections; ++k) flip[k] = p.words[lane_word(p, kind_err(m, 1), k)] < 0;
  for (int j = 1; j <= m; ++j) {
    for (int k = 0; k < kLanes; ++k) {
      const std::int64_t e = p.words[lane_word(p, kind_err(m, j), k)];
      buf[k] = flip[k] ? -e : e;
    }
    c.ee[j] = T::load(buf);
  }
  // The constants that the biases and r's offset leave, per lane, all in lo's preload, the ones at
  // acc's scale times 2^L (they pass its floor exactly). With Y = 2^(D-1+s), u' = u + Y, w' = w +
  // Y, r = e + 2^(F-1) (or 2^F - 1 less that), and the biased acc' = acc + Y 2^F:
  //   lo' = 2^(F-1+L) - Y (sum W) + 2^L G + sum W_b u' + sum W_a w'   (= lo + 2^L G)
  //   G   = Y 2^F - Y (sum H) - (sum E) (2^(F-1) - flip (2^F - 1)).
  for (int k = 0; k < kLanes; ++k) {
    std::int64_t sum_w = 0, sum_h = 0, sum_e = 0;
    for (int i = 0; i <= m; ++i) {
      sum_w += p.words[lane_word(p, kind_lo_b(m, i), k)];
      sum_h += p.words[lane_word(p, kind_hi_b(m, i), k)];
    }
    for (int j = 1; j <= m; ++j) {
      sum_w += p.words[lane_word(p, kind_lo_a(m, j), k)];
      sum_h += p.words[lane_word(p, kind_hi_a(m, j), k)];
      sum_e += p.words[lane_word(p, kind_err(m, j), k)];
    }
    const std::int64_t g =
        (p.bias << p.frac) - p.bias * sum_h - sum_e * (p.half_f - (flip[k] ? p.mask_f : 0));
    buf[k] = k < sections
                 ? (p.half_f << p.split) - p.bias * sum_w + g * (std::int64_t{1} << p.split)
                 : 0;
    flip[k] = flip[k] ? p.mask_f : 0;
  }
  c.pre_lo = T::load(buf);
  for (int k = 0; k < kLanes; ++k) flip[k] <<= r_shift;
  c.flip = T::load(flip);
  c.shift_lo = T::set1(p.split);
  c.shift_acc = T::set1(kMergedSums ? p.split + p.frac : p.frac);
  c.mask_f = T::set1(p.mask_f << r_shift);
  c.ext_max = T::set1(p.ext_max - p.ext_min);
}

// The lanes' state from the load registers (lane k's u from line k, w from line k + 1, r from
// line K + 1 + k; line l's words of ages 1..M at history[l M ..]).
template <class T, int m, Sums kSums>
FLANGE_TARGET inline void load_state(const Plan& p, std::int64_t* history, const std::int64_t* flip,
                                     State<T>& s) {
  constexpr int kLanes = T::kLanes;
  const int sections = p.sections;
  const int r_shift = kSums == Sums::kMerged ? p.split : 0;
  alignas(64) std::int64_t buf[kLanes];
  const auto line = [&](int l, int age) -> std::int64_t& {
    return history[static_cast<std::size_t>(l * m + age - 1)];
  };
  // The load registers' values to the lanes' biased form: u and w plus Y, e plus 2^(F-1) and
  // negated within F bits (x ^ (2^F - 1)) where r is kept negated.
  const auto gather = [&](int first_line, int age, std::int64_t plus, bool error) {
    for (int k = 0; k < kLanes; ++k) {
      if (k >= sections) {
        buf[k] = 0;
      } else if (error) {
        buf[k] = ((line(first_line + k, age) + plus) << r_shift) ^ flip[k];
      } else {
        buf[k] = line(first_line + k, age) + plus;
      }
    }
    return T::load(buf);
  };
  s.u1 = gather(0, 1, p.bias, false);
  s.w1 = gather(1, 1, p.bias, false);
  s.r1 = gather(sections + 1, 1, p.half_f, true);
  s.u2 = m == 2 ? gather(0, 2, p.bias, false) : T::set1(0);
  s.w2 = m == 2 ? gather(1, 2, p.bias, false) : T::set1(0);
  s.r2 = m == 2 ? gather(sections + 1, 2, p.half_f, true) : T::set1(0);
  s.y1 = s.y2 = T::set1(0);
}

// Back to the load registers: line k's words from lane k's input history, line K from the last
// lane's output history, the errors less 2^(F-1); the biases undone.
template <class T, int m, Sums kSums>
FLANGE_TARGET inline void store_state(const Plan& p, const State<T>& s, const std::int64_t* flip,
                                      std::int64_t* history) {
  const int sections = p.sections;
  const int r_shift = kSums == Sums::kMerged ? p.split : 0;
  alignas(64) std::int64_t buf[T::kLanes];
  const auto line = [&](int l, int age) -> std::int64_t& {
    return history[static_cast<std::size_t>(l * m + age - 1)];
  };
  const auto scatter = [&](typename T::V v, int first_line, int age, std::int64_t minus,
                           bool error) {
    T::store(buf, v);
    for (int k = 0; k < sections; ++k) {
      line(first_line + k, age) = (error ? (buf[k] ^ flip[k]) >> r_shift : buf[k]) - minus;
    }
  };
  for (int age = 1; age <= m; ++age) {
    scatter(age == 1 ? s.u1 : s.u2, 0, age, p.bias, false);
    scatter(age == 1 ? s.r1 : s.r2, sections + 1, age, p.half_f, true);
    T::store(buf, age == 1 ? s.w1 : s.w2);
    line(sections, age) = buf[sections - 1] - p.bias;
  }
}

// The inputs of steps [c0, c1) of n samples as x << s, widened and biased by Y (shift_in = s,
// bias = Y in every lane), x[c0 + j] at xs[kLanes - 1 + j]; 0 past the last sample.
template <class T>
FLANGE_TARGET inline void widen_inputs(const Plan& p, const std::int32_t* in, std::size_t n,
                                       std::size_t c0, std::size_t c1, std::int64_t* xs,
                                       typename T::V shift_in, typename T::V bias) {
  constexpr int kLanes = T::kLanes;
  const std::size_t inputs_end = std::max(c0, std::min(c1, n));
  std::size_t t = c0;
  for (; t + T::kLanes <= inputs_end; t += T::kLanes) {
    T::store(xs + kLanes - 1 + (t - c0), T::add(T::sllv(T::widen32(in + t), shift_in), bias));
  }
  for (; t < inputs_end; ++t) xs[kLanes - 1 + (t - c0)] = (std::int64_t{in[t]} << p.shift) + p.bias;
  std::fill(xs + kLanes - 1 + (inputs_end - c0), xs + kLanes - 1 + (c1 - c0), 0);
}

// Where the steps of the chunk from c0 put what they make: the last section's y_ext of step t as
// ys[t - c0], by a masked store of lane K - 1's low dword alone at y_base + 4 (t - c0), 2(K - 1)
// dwords before ys[t - c0] (masked-out lanes never touch memory); the samples' clips in the ring.
template <class T>
struct StepOutputs {
  std::uintptr_t y_base;
  typename T::DwordMask y_mask;
  std::uint8_t* ring;
  std::size_t* dirty_until;  // every sample marked in the ring is below this
};

// Step t of the chunk from c0 while the lanes fill or drain: section k is active while its sample
// t - 2k is one of the n. With the clip test.
template <class T, int m, Sums kSums, bool kSignedHa1>
FLANGE_TARGET inline void masked_step(const Words<T, m>& c, State<T>& s, const std::int64_t* xs,
                                      std::size_t c0, std::size_t t, int sections, std::size_t n,
                                      StepOutputs<T> o) {
  unsigned active = 0;
  for (int k = 0; k < sections; ++k) {
    const auto lag = static_cast<std::size_t>(2 * k);
    if (t >= lag && t - lag < n) active |= 1u << k;
  }
  const __mmask8 clipped =
      lane_step<T, m, kSums, kSignedHa1, true>(c, s, xs + (t - c0), static_cast<__mmask8>(active));
  if (clipped) record_clips(o.ring, *o.dirty_until, clipped, t);
  if (active >> (sections - 1)) T::store_dword(o.y_base + 4 * (t - c0), o.y_mask, s.y1);
}

// Steps [begin, end) of the chunk from c0 with every lane active (lane_mask): first without the
// clip test, tracking y_ext's range; if some y_ext left it (a bit of out_of_range set: a clip,
// rare for a useful filter), back to the state before and again with the test.
template <class T, int m, Sums kSums, bool kSignedHa1>
FLANGE_TARGET inline void full_steps(const Words<T, m>& c, State<T>& s, const std::int64_t* xs,
                                     std::size_t c0, std::size_t begin, std::size_t end,
                                     __mmask8 lane_mask, typename T::V out_of_range,
                                     StepOutputs<T> o) {
  const State<T> before = s;
  Seen<T> seen{T::set1(0)};
  std::size_t t = begin;
  for (; t + 1 < end; t += 2) {  // two steps a turn: the history moves by renaming
    lane_step<T, m, kSums, kSignedHa1, false, false>(c, s, xs + (t - c0), lane_mask, &seen);
    T::store_dword(o.y_base + 4 * (t - c0), o.y_mask, s.y1);
    lane_step<T, m, kSums, kSignedHa1, false, false>(c, s, xs + (t + 1 - c0), lane_mask, &seen);
    T::store_dword(o.y_base + 4 * (t + 1 - c0), o.y_mask, s.y1);
  }
  if (t < end) {
    lane_step<T, m, kSums, kSignedHa1, false, false>(c, s, xs + (t - c0), lane_mask, &seen);
    T::store_dword(o.y_base + 4 * (t - c0), o.y_mask, s.y1);
  }
  if (T::any_common(seen.bits, out_of_range)) {
    s = before;
    for (t = begin; t < end; ++t) {
      const __mmask8 clipped =
          lane_step<T, m, kSums, kSignedHa1, false>(c, s, xs + (t - c0), lane_mask);
      if (clipped) record_clips(o.ring, *o.dirty_until, clipped, t);
      T::store_dword(o.y_base + 4 * (t - c0), o.y_mask, s.y1);
    }
  }
}

// The kernel for `lanes` = T::kLanes, M = kOrder, the sums and the sign of the H_a[1] words.
// Section k works on sample t - 2k at step t, so n samples take n + 2(K - 1) steps, run in chunks
// of kChunk and, where every lane is active, in parts of kPart without the clip test first. Its
// helpers are inlined: a call in the loop would make the compiler keep the lanes' state in memory.
template <class T, int kOrder, Sums kSums, bool kSignedHa1>
void run_lanes(const Plan& p, std::int64_t* history, const std::int32_t* in, SampleResult* out,
               std::size_t n) {
  using V = typename T::V;
  constexpr int m = kOrder;
  constexpr int kLanes = T::kLanes;
  const int sections = p.sections;
  alignas(64) std::int64_t flip[kLanes] = {};
  Words<T, m> c;
  lane_words<T, m, kSums>(p, flip, c);
  const auto lane_mask = static_cast<__mmask8>((1u << sections) - 1);
  const V out_of_range = T::set1(~(2 * p.bias - 1));  // 2Y = 2^(D+s)

  State<T> s;
  load_state<T, m, kSums>(p, history, flip, s);

  const int last = sections - 1;
  const std::size_t skew = static_cast<std::size_t>(2 * last);
  const std::size_t steps = n + skew;
  // The inputs x << s of a chunk of steps, widened: x[c0 + j] at [kLanes - 1 + j], the top lane of
  // the load at [j] (only the top lane is used).
  alignas(64) std::int64_t xs[kChunk + kLanes] = {};
  // The last section's y_ext of the samples a chunk finishes, [c0 - skew, c1 - skew), one per
  // step (StepOutputs). finish_samples then writes them to out.
  alignas(64) std::int32_t ys[kChunk];
  std::uint8_t ring[kRing] = {};
  std::size_t dirty_until = 0;  // every sample marked in the ring is below this
  const auto y_mask = static_cast<typename T::DwordMask>(1u << (2 * last));
  const std::uintptr_t y_base =
      reinterpret_cast<std::uintptr_t>(ys) - 8 * static_cast<std::uintptr_t>(last);
  const StepOutputs<T> o{y_base, y_mask, ring, &dirty_until};
  const V shift_in = T::set1(p.shift), bias = T::set1(p.bias);
  for (std::size_t c0 = 0; c0 < steps; c0 += kChunk) {
    const std::size_t c1 = std::min(steps, c0 + kChunk);
    widen_inputs<T>(p, in, n, c0, c1, xs, shift_in, bias);
    std::size_t t = c0;
    for (; t < std::min(c1, skew); ++t) {
      masked_step<T, m, kSums, kSignedHa1>(c, s, xs, c0, t, sections, n, o);
    }
    // Every lane active: a part of kPart steps at a time; a rerun repeats only the part that left
    // the range.
    const std::size_t full_end = std::max(t, std::min(c1, n));
    while (t < full_end) {
      const std::size_t part_end = std::min(full_end, t + kPart);
      full_steps<T, m, kSums, kSignedHa1>(c, s, xs, c0, t, part_end, lane_mask, out_of_range, o);
      t = part_end;
    }
    for (; t < c1; ++t) masked_step<T, m, kSums, kSignedHa1>(c, s, xs, c0, t, sections, n, o);
    // The samples this chunk finished; ys[j] is sample c0 + j - skew.
    const std::size_t first = std::max(c0, skew), end = std::max(c1, skew);
    finish_samples<T>(p, ys + (first - c0), ring, first - skew >= dirty_until, out, first - skew,
                      end - skew);
  }
  store_state<T, m, kSums>(p, s, flip, history);
}

}  // namespace

#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif

void run(const Plan& p, std::int64_t* history, const std::int32_t* in, SampleResult* out,
         std::size_t n) {
  if (!cpu_has_instructions(p.sums)) throw std::logic_error("vector kernel: no AVX-512 for it");
  const auto for_sign = [&]<class T, int kOrder>() {
    if (p.sums == Sums::kMerged)
      return run_lanes<T, kOrder, Sums::kMerged, false>(p, history, in, out, n);
    if (p.signed_ha1) return run_lanes<T, kOrder, Sums::kSplit, true>(p, history, in, out, n);
    return run_lanes<T, kOrder, Sums::kSplit, false>(p, history, in, out, n);
  };
  if (p.lanes == 4) {
    if (p.order == 2) return for_sign.template operator()<Ymm, 2>();
    return for_sign.template operator()<Ymm, 1>();
  }
  if (p.order == 2) return for_sign.template operator()<Zmm, 2>();
  return for_sign.template operator()<Zmm, 1>();
}

#else

void run(const Plan&, std::int64_t*, const std::int32_t*, SampleResult*, std::size_t) {
  throw std::logic_error("vector kernel: not built for this architecture");
}

#endif

}  // namespace flange::model::vector
