// SPDX-License-Identifier: MIT
// Time per design for orders 1 to 32: the float design alone (the baseline, same run) and the
// full `flange design` path without file output (design, SOS scaling, quantisation, analysis).
#include <benchmark/benchmark.h>

#include "generator.h"

namespace {

using flange::coeffs::DesignRequest;
using flange::coeffs::Structure;

DesignRequest request_for(int order) {
  DesignRequest request;
  request.fs_hz = 100.0;
  request.order = order;
  request.fc_hz = 10.0;
  request.structure = Structure::kSos;
  return request;
}

void FloatDesignOnly(benchmark::State& state) {
  const int order = static_cast<int>(state.range(0));
  for (auto _ : state) {
    benchmark::DoNotOptimize(flange::coeffs::design_butterworth(order, 10.0, 100.0, {}));
  }
}

void DesignAndQuantiseSos(benchmark::State& state) {
  const DesignRequest request = request_for(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    benchmark::DoNotOptimize(flange::coeffs::generate_design(request, "bench"));
  }
}

void DesignAndQuantiseWithSpec(benchmark::State& state) {
  // The thesis measurement spec: order selection plus the mask analysis.
  DesignRequest request;
  request.fs_hz = 6.0;
  request.fp_hz = 0.21128;
  request.fa_hz = 0.975;
  request.ap_db = 0.1737;
  request.aa_db = 40.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(flange::coeffs::generate_design(request, "bench"));
  }
}

}  // namespace

BENCHMARK(FloatDesignOnly)->DenseRange(1, 32, 1)->Unit(benchmark::kMicrosecond);
BENCHMARK(DesignAndQuantiseSos)->DenseRange(1, 32, 1)->Unit(benchmark::kMicrosecond);
BENCHMARK(DesignAndQuantiseWithSpec)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
