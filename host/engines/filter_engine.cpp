// SPDX-License-Identifier: MIT
#include "filter_engine.h"

#include <cmath>
#include <stdexcept>

#include "filter_json.h"
#include "iir_sample_model.h"
#include "reference_filter.h"
#include "rtl_engine.h"

namespace flange::host {

namespace {

// The bit-accurate model of the core, streaming back to back. Only the samples are wanted here, so
// it runs the sample-level twin of the cycle model (model/iir_sample_model.h), equal to it on
// every word and flag.
class ModelEngine : public FilterEngine {
 public:
  explicit ModelEngine(const std::filesystem::path& filter_json)
      : core_(model::load_core_config(filter_json)),
        gain_(model::load_float_design(filter_json).leftover_gain),
        full_scale_(std::ldexp(1.0, core_.config().sample_width - 1)) {}

  std::string name() const override { return "model"; }
  void process(const std::vector<EngineSample>& in, std::vector<EngineOutput>& out) override {
    words_.resize(in.size());
    results_.resize(in.size());
    for (std::size_t k = 0; k < in.size(); ++k) words_[k] = in[k].word;
    core_.filter(words_, results_);
    out.resize(in.size());
    for (std::size_t k = 0; k < in.size(); ++k) {
      const model::SampleResult& result = results_[k];
      out[k] = {gain_ * result.sample / full_scale_, result.saturated, result.sample};
    }
  }

 private:
  model::IirSampleModel core_;
  double gain_;
  double full_scale_;
  std::vector<std::int32_t> words_;           // reused from block to block
  std::vector<model::SampleResult> results_;  // reused from block to block
};

// The double-precision second-order sections of the same design.
class FloatEngine : public FilterEngine {
 public:
  explicit FloatEngine(const std::filesystem::path& filter_json)
      : filter_(model::load_float_design(filter_json)) {}
  std::string name() const override { return "float"; }
  void process(const std::vector<EngineSample>& in, std::vector<EngineOutput>& out) override {
    out.resize(in.size());
    for (std::size_t k = 0; k < in.size(); ++k) out[k] = {filter_.step(in[k].unit), false};
  }

 private:
  model::ReferenceFilter filter_;
};

}  // namespace

std::unique_ptr<FilterEngine> make_filter_engine(const std::string& engine,
                                                 const std::filesystem::path& filter_json) {
  if (engine == "model") return std::make_unique<ModelEngine>(filter_json);
  if (engine == "float") return std::make_unique<FloatEngine>(filter_json);
  if (engine == "rtl") return make_rtl_engine(filter_json);
  throw std::invalid_argument("--engine " + engine + ": valid engines are model, rtl, float");
}

}  // namespace flange::host
