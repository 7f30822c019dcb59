// SPDX-License-Identifier: MIT
// Nanoseconds a number for the parsers `flange run` could read a recording with: libstdc++'s
// std::from_chars (the baseline, same run) and fast_float's, which the recording reader uses
// (host/recording/recording_columns.cpp; docs/benchmarks.md, `flange run`). The numbers are those
// of a bench recording: times, clearances, temperatures and voltages with six decimals.
#include <benchmark/benchmark.h>
#include <fast_float/fast_float.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

// 4 x 100,000 fields as `flange simulate --scenario bench` writes them (t at 6 Hz, a clearance
// sweep, a heating curve, a voltage), one after the other in one buffer.
struct Fields {
  std::string text;
  std::vector<std::size_t> starts, ends;
};

const Fields& bench_fields() {
  static const Fields fields = [] {
    Fields f;
    char number[32];
    for (int i = 0; i < 100000; ++i) {
      const double t = i / 6.0;
      const double values[4] = {
          t, 1.5 + 8.5 * std::abs(std::sin(t / 95.0)), 20.0 + 75.0 * (1.0 - std::exp(-t / 400.0)),
          0.8 + 8.9 * std::abs(std::sin(t / 95.0)) + 0.07 * std::sin(7.0 * t)};
      for (const double v : values) {
        const int n = std::snprintf(number, sizeof number, "%.6f", v);
        f.starts.push_back(f.text.size());
        f.text.append(number, static_cast<std::size_t>(n));
        f.ends.push_back(f.text.size());
        f.text.push_back(',');
      }
    }
    return f;
  }();
  return fields;
}

template <typename Parse>
void parse_all(benchmark::State& state, Parse parse) {
  const Fields& f = bench_fields();
  const char* base = f.text.data();
  for (auto _ : state) {
    double sum = 0.0;
    for (std::size_t k = 0; k < f.starts.size(); ++k) {
      double value = 0.0;
      parse(base + f.starts[k], base + f.ends[k], value);
      sum += value;
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(f.starts.size()));
}

void StdFromChars(benchmark::State& state) {
  parse_all(state, [](const char* b, const char* e, double& v) { std::from_chars(b, e, v); });
}

void FastFloatFromChars(benchmark::State& state) {
  parse_all(state,
            [](const char* b, const char* e, double& v) { fast_float::from_chars(b, e, v); });
}

}  // namespace

BENCHMARK(StdFromChars);
BENCHMARK(FastFloatFromChars);
BENCHMARK_MAIN();
