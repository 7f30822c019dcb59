// SPDX-License-Identifier: MIT
// The sample model's throughput (model/iir_sample_model.h) beside the cycle model it is equal to
// (IirCore::step) and the double-precision ReferenceFilter (the baseline: process() on the block,
// and step() per sample), on the same 1,000,000
// input words of measurement_sos and vehicle_sos, in one run (docs/benchmarks_core.md, "Sample
// model"). Every benchmark filters the whole block per iteration from a zero state.
//
//   build/bench/sample_model_bench [--dump_dir=DIR] [Google Benchmark flags]
//
// --dump_dir=DIR also writes, for bench/sosfilt_peer.sh, DIR/<set>.x.i32 (the input words, int32
// in the machine's byte order), DIR/<set>.reference.f64 (ReferenceFilter's outputs in full-scale
// units, double) and DIR/manifest.json (per set: its filter.json, D, the two files).
#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "filter_json.h"
#include "iir_core.h"
#include "iir_sample_model.h"
#include "rate_collector.h"
#include "reference_filter.h"

namespace {

constexpr std::size_t kSamples = 1'000'000;
constexpr std::uint64_t kSeed = 20261122;

struct BenchSet {
  std::string name;
  std::filesystem::path json;
  flange::model::CoreConfig config;
  flange::model::FloatDesign design;
  std::vector<std::int32_t> words;  // uniform over the full D-bit range
  std::vector<double> units;        // the same words in full-scale units, the reference's input
};

BenchSet load_set(const std::string& name) {
  BenchSet set;
  set.name = name;
  set.json = std::filesystem::path(FLANGE_SOURCE_DIR) / "coeffs" / name / "filter.json";
  set.config = flange::model::load_core_config(set.json);
  set.design = flange::model::load_float_design(set.json);
  const int d = set.config.sample_width;
  const double full_scale = std::ldexp(1.0, d - 1);
  // The raw generator's top D bits as a signed word: the same words on every platform.
  std::mt19937_64 rng(kSeed);
  for (std::size_t i = 0; i < kSamples; ++i) {
    const auto bits = static_cast<std::int64_t>(rng() >> (64 - d));
    const auto word = static_cast<std::int32_t>(bits - (std::int64_t{1} << (d - 1)));
    set.words.push_back(word);
    set.units.push_back(word / full_scale);
  }
  return set;
}

void sample_model_block(benchmark::State& state, const BenchSet& set,
                        flange::model::SampleKernel kernel = flange::model::SampleKernel::kAuto) {
  flange::model::IirSampleModel model(set.config, kernel);
  std::vector<flange::model::SampleResult> out(set.words.size());
  for (auto _ : state) {
    model.reset();
    model.filter(set.words, out);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(set.words.size()));
}

// The two vector kernels, each forced (kAuto takes one of them by the CPU's maker).
void split_vector_block(benchmark::State& state, const BenchSet& set) {
  sample_model_block(state, set, flange::model::SampleKernel::kVector);
}
void merged_vector_block(benchmark::State& state, const BenchSet& set) {
  sample_model_block(state, set, flange::model::SampleKernel::kVectorMerged);
}

void sample_model_step(benchmark::State& state, const BenchSet& set) {
  flange::model::IirSampleModel model(set.config);
  for (auto _ : state) {
    model.reset();
    for (const std::int32_t x : set.words) benchmark::DoNotOptimize(model.step(x));
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(set.words.size()));
}

void cycle_model_step(benchmark::State& state, const BenchSet& set) {
  for (auto _ : state) {
    flange::model::IirCore core(set.config);  // the cycle count grows: a fresh core per block
    for (const std::int32_t x : set.words) benchmark::DoNotOptimize(core.step(x));
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(set.words.size()));
}

void reference_block(benchmark::State& state, const BenchSet& set) {
  flange::model::ReferenceFilter filter(set.design);
  std::vector<double> out(set.units.size());
  for (auto _ : state) {
    filter.reset();
    filter.process(set.units, out);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(set.units.size()));
}

void reference_step(benchmark::State& state, const BenchSet& set) {
  flange::model::ReferenceFilter filter(set.design);
  for (auto _ : state) {
    filter.reset();
    for (const double x : set.units) benchmark::DoNotOptimize(filter.step(x));
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(set.units.size()));
}

using flange::bench::RateCollector;

std::string ratio_text(std::optional<double> numerator, std::optional<double> denominator) {
  if (!numerator || !denominator) return "-";
  return fmt::format("{:.3g}", *numerator / *denominator);
}

std::string rate_text(std::optional<double> rate) {
  return rate ? fmt::format("{:.2f} M", *rate / 1e6) : "-";
}

void dump(const std::vector<BenchSet>& sets, const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  nlohmann::json manifest = nlohmann::json::array();
  for (const BenchSet& set : sets) {
    const std::filesystem::path x_file = dir / (set.name + ".x.i32");
    const std::filesystem::path y_file = dir / (set.name + ".reference.f64");
    std::ofstream(x_file, std::ios::binary)
        .write(reinterpret_cast<const char*>(set.words.data()),
               static_cast<std::streamsize>(set.words.size() * sizeof(std::int32_t)));
    flange::model::ReferenceFilter filter(set.design);
    std::vector<double> y(set.units.size());
    filter.process(set.units, y);
    std::ofstream(y_file, std::ios::binary)
        .write(reinterpret_cast<const char*>(y.data()),
               static_cast<std::streamsize>(y.size() * sizeof(double)));
    manifest.push_back({{"name", set.name},
                        {"filter_json", set.json.string()},
                        {"sample_width", set.config.sample_width},
                        {"x", x_file.string()},
                        {"reference", y_file.string()}});
  }
  std::ofstream(dir / "manifest.json") << manifest.dump(2) << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  std::optional<std::filesystem::path> dump_dir;
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i) {
    constexpr const char* kDumpFlag = "--dump_dir=";
    if (std::strncmp(argv[i], kDumpFlag, std::strlen(kDumpFlag)) == 0) {
      dump_dir = argv[i] + std::strlen(kDumpFlag);
    } else {
      args.push_back(argv[i]);
    }
  }
  int bench_argc = static_cast<int>(args.size());
  benchmark::Initialize(&bench_argc, args.data());
  if (benchmark::ReportUnrecognizedArguments(bench_argc, args.data())) return 1;

  std::vector<BenchSet> sets;
  try {
    for (const char* name : {"measurement_sos", "vehicle_sos"}) sets.push_back(load_set(name));
    if (dump_dir) dump(sets, *dump_dir);
  } catch (const std::exception& e) {
    std::cerr << "sample_model_bench: " << e.what() << "\n";
    return 1;
  }

  for (const BenchSet& set : sets) {
    const auto add = [&set](const std::string& what,
                            void (*fn)(benchmark::State&, const BenchSet&)) {
      benchmark::RegisterBenchmark((what + "/" + set.name).c_str(), [&set,
                                                                     fn](benchmark::State& s) {
        fn(s, set);
      })->Unit(benchmark::kMillisecond);
    };
    add("SampleModel", [](benchmark::State& s, const BenchSet& b) { sample_model_block(s, b); });
    using flange::model::SampleKernel;
    if (flange::model::IirSampleModel::kernel_available(set.config, SampleKernel::kVector)) {
      add("SampleModelVector", split_vector_block);
    }
    if (flange::model::IirSampleModel::kernel_available(set.config, SampleKernel::kVectorMerged)) {
      add("SampleModelVectorMerged", merged_vector_block);
    }
    add("SampleModelStep", sample_model_step);
    add("IirCore", cycle_model_step);
    add("ReferenceFilter", reference_block);
    add("ReferenceFilterStep", reference_step);
  }
  RateCollector reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);

  std::cout << fmt::format(
      "\nSamples/s on one core, {} uniform random words per block; SampleModel = "
      "IirSampleModel::filter on the block, step = IirSampleModel::step per sample; reference = "
      "ReferenceFilter::process on the block, ref step = ReferenceFilter::step per sample\n",
      kSamples);
  for (const BenchSet& set : sets) {
    std::cout << fmt::format(
        "{}: kAuto takes the {} kernel; vector (split sums) {}, vector-merged {}\n", set.name,
        to_string(flange::model::IirSampleModel(set.config).kernel()),
        rate_text(reporter.rate("SampleModelVector/" + set.name)),
        rate_text(reporter.rate("SampleModelVectorMerged/" + set.name)));
  }
  std::cout << fmt::format("{:<16} {:>11} {:>11} {:>11} {:>11} {:>11} {:>12} {:>11}\n", "set",
                           "sample", "step", "IirCore", "reference", "ref step", "sample/core",
                           "sample/ref");
  for (const BenchSet& set : sets) {
    const auto sample = reporter.rate("SampleModel/" + set.name);
    const auto step = reporter.rate("SampleModelStep/" + set.name);
    const auto core = reporter.rate("IirCore/" + set.name);
    const auto reference = reporter.rate("ReferenceFilter/" + set.name);
    const auto reference_stepped = reporter.rate("ReferenceFilterStep/" + set.name);
    std::cout << fmt::format("{:<16} {:>11} {:>11} {:>11} {:>11} {:>11} {:>12} {:>11}\n", set.name,
                             rate_text(sample), rate_text(step), rate_text(core),
                             rate_text(reference), rate_text(reference_stepped),
                             ratio_text(sample, core), ratio_text(sample, reference));
  }
  benchmark::Shutdown();
  return 0;
}
