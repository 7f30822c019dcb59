// SPDX-License-Identifier: MIT
// The loop-carried paths of the sample model's vector kernel (model/iir_sample_vector.cpp), each
// timed alone as a chain of dependent 256-bit instructions, in cycles of this processor's clock
// (a 3-cycle imul chain timed just before each row is the clock; on a loaded machine the rows
// are worth little). What the instruction latencies add up
// to is printed beside each, so the forwarding delays between the multiply-add unit and the
// shifts and adds show (docs/benchmarks_core.md, "Sample model").
//
//   build/bench/vector_chain_bench [iterations, default 200000000]
//
// x86-64 with AVX-512F, VL and IFMA only; elsewhere it says so and exits 2.
#include <chrono>
#include <cstdio>
#include <cstdlib>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define FLANGE_AVX512 __attribute__((target("avx512f,avx512vl,avx512ifma")))

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The clock in GHz: four dependent 64-bit multiplies (3 cycles each) per turn.
double clock_ghz(long turns) {
  long x = 3, y = 7;
  asm("" : "+r"(y));
  const auto t0 = std::chrono::steady_clock::now();
  for (long i = 0; i < turns; ++i) {
    x *= y;
    x *= y;
    x *= y;
    x *= y;
    asm("" : "+r"(x));
  }
  const double s = seconds_since(t0);
  asm("" : : "r"(x));
  return 12.0 * static_cast<double>(turns) / s / 1e9;
}

// Every operand but the chain's own is opaque to the compiler, so it cannot fold them.
struct Operands {
  __m256i lo_pre, hi, word_a, word_e, word_h, shift_lo, shift_f, mask_f, zero;
};

template <class Step>
FLANGE_AVX512 double cycles_per_turn(long turns, double ghz, Step step) {
  __m256i acc = _mm256_set1_epi64x(1);
  const auto t0 = std::chrono::steady_clock::now();
  for (long i = 0; i < turns; ++i) acc = step(acc);
  const double s = seconds_since(t0);
  asm("" : : "v"(acc));
  return s * ghz * 1e9 / static_cast<double>(turns);
}

FLANGE_AVX512 void run(long turns) {
  Operands o{_mm256_set1_epi64x(3),  _mm256_set1_epi64x(5),       _mm256_set1_epi64x(7),
             _mm256_set1_epi64x(9),  _mm256_set1_epi64x(11),      _mm256_set1_epi64x(17),
             _mm256_set1_epi64x(20), _mm256_set1_epi64x(0xfffff), _mm256_set1_epi64x(0)};
  asm("" : "+v"(o.lo_pre), "+v"(o.hi), "+v"(o.word_a), "+v"(o.word_e), "+v"(o.word_h));
  asm("" : "+v"(o.shift_lo), "+v"(o.shift_f), "+v"(o.mask_f), "+v"(o.zero));
  // The clock is timed again before each row: a shared machine's clock moves.
  std::printf("%-62s %8s %8s %6s\n", "chain", "cycles", "latency", "GHz");
  const auto row = [&](const char* name, int latency, auto step) {
    const double ghz = clock_ghz(turns / 4);
    std::printf("%-62s %8.2f %8d %6.2f\n", name, cycles_per_turn(turns, ghz, step), latency, ghz);
  };
  row("vpmadd52luq accumulator -> accumulator", 4,
      [&](__m256i a) FLANGE_AVX512 { return _mm256_madd52lo_epu64(a, o.word_a, o.word_e); });
  row("vpmuldq", 5, [&](__m256i a) FLANGE_AVX512 { return _mm256_mul_epi32(a, o.word_a); });
  row("vpmadd52luq, vpaddq", 5, [&](__m256i a) FLANGE_AVX512 {
    return _mm256_add_epi64(_mm256_madd52lo_epu64(o.lo_pre, o.word_a, a), o.zero);
  });
  row("vpmadd52luq, vpsravq", 5, [&](__m256i a) FLANGE_AVX512 {
    return _mm256_srav_epi64(_mm256_madd52lo_epu64(o.lo_pre, o.word_a, a), o.zero);
  });
  row("vpmuldq, vpaddq", 6, [&](__m256i a) FLANGE_AVX512 {
    return _mm256_add_epi64(_mm256_mul_epi32(a, o.word_a), o.zero);
  });
  // The kernel's paths: y = acc >>> F, r = acc & mask; lo's newest term a multiply-add, moved to
  // the top and shifted down by L + 12; the E and H terms exact products; three adds to acc.
  row("y path: >>> F, multiply-add, << 12, >>> (L+12), add", 8, [&](__m256i acc) FLANGE_AVX512 {
    const __m256i y = _mm256_srav_epi64(acc, o.shift_f);
    const __m256i lo = _mm256_slli_epi64(_mm256_madd52lo_epu64(o.lo_pre, o.word_a, y), 12);
    return _mm256_add_epi64(o.hi, _mm256_srav_epi64(lo, o.shift_lo));
  });
  row("y path with an exact product: >>> F, vpmuldq, add, >>> L, add", 9,
      [&](__m256i acc) FLANGE_AVX512 {
        const __m256i y = _mm256_srav_epi64(acc, o.shift_f);
        const __m256i lo = _mm256_add_epi64(o.lo_pre, _mm256_mul_epi32(o.word_a, y));
        return _mm256_add_epi64(o.hi, _mm256_srav_epi64(lo, o.shift_lo));
      });
  row("the kernel's step: y, error and H paths together", 9, [&](__m256i acc) FLANGE_AVX512 {
    const __m256i y = _mm256_srav_epi64(acc, o.shift_f);
    const __m256i r = _mm256_and_si256(acc, o.mask_f);
    const __m256i lo = _mm256_slli_epi64(_mm256_madd52lo_epu64(o.lo_pre, o.word_a, y), 12);
    __m256i hi = _mm256_add_epi64(_mm256_add_epi64(o.hi, _mm256_mul_epi32(o.word_e, r)),
                                  _mm256_mul_epi32(o.word_h, y));
    asm("" : "+v"(hi));  // as the kernel keeps it: hi summed on its own
    return _mm256_add_epi64(hi, _mm256_srav_epi64(lo, o.shift_lo));
  });
}

}  // namespace

int main(int argc, char** argv) {
  if (!(__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
        __builtin_cpu_supports("avx512ifma"))) {
    std::fprintf(stderr, "vector_chain_bench: this processor has no AVX-512 IFMA\n");
    return 2;
  }
  const long turns = argc > 1 ? std::atol(argv[1]) : 200'000'000L;
  if (turns < 1000) {
    std::fprintf(stderr, "vector_chain_bench: iterations must be at least 1000, got %s\n", argv[1]);
    return 2;
  }
  run(turns);
  return 0;
}

#else

int main() {
  std::fprintf(stderr, "vector_chain_bench: built for x86-64 with GCC or Clang only\n");
  return 2;
}

#endif
