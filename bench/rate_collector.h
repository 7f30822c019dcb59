// SPDX-License-Identifier: MIT
// The console reporter of the benchmarks that print ratio tables: Google Benchmark's console
// output, plus each benchmark's samples/s (items_per_second) kept for the ratios.
#pragma once

#include <benchmark/benchmark.h>
#include <unistd.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace flange::bench {

class RateCollector : public benchmark::ConsoleReporter {
 public:
  // Counters inline (name=value): the benchmarks carry different counters, and a table would
  // repeat its header for each. Colour only on a terminal.
  RateCollector() : ConsoleReporter(::isatty(STDOUT_FILENO) != 0 ? OO_Color : OO_None) {}

  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      const auto rate = run.counters.find("items_per_second");
      if (run.error_occurred || rate == run.counters.end()) continue;
      const std::string name = run.run_name.str();
      if (run.run_type == Run::RT_Aggregate) {
        if (run.aggregate_name == "median") median_[name] = rate->second.value;
      } else {
        samples_[name].push_back(rate->second.value);
      }
    }
  }

  // The median over repetitions when there were several, else the single run's rate.
  std::optional<double> rate(const std::string& name) const {
    if (const auto it = median_.find(name); it != median_.end()) return it->second;
    if (const auto it = samples_.find(name); it != samples_.end() && !it->second.empty()) {
      double sum = 0.0;
      for (double v : it->second) sum += v;
      return sum / static_cast<double>(it->second.size());
    }
    return std::nullopt;
  }

 private:
  std::map<std::string, double> median_;
  std::map<std::string, std::vector<double>> samples_;
};

}  // namespace flange::bench
