// SPDX-License-Identifier: MIT
#include "filter_engine.h"

#include <fmt/format.h>

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
  ModelEngine(const std::filesystem::path& filter_json, int channel)
      : core_(model::load_core_config(filter_json).channel_config(channel)),
        gain_(model::load_float_design(filter_json, channel).leftover_gain),
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
  FloatEngine(const std::filesystem::path& filter_json, int channel)
      : filter_(model::load_float_design(filter_json, channel)) {}
  std::string name() const override { return "float"; }
  void process(const std::vector<EngineSample>& in, std::vector<EngineOutput>& out) override {
    units_.resize(in.size());
    for (std::size_t k = 0; k < in.size(); ++k) units_[k] = in[k].unit;
    filter_.process(units_, units_);  // step() over the block, bit for bit
    out.resize(in.size());
    for (std::size_t k = 0; k < in.size(); ++k) out[k] = {units_[k], false};
  }

 private:
  model::ReferenceFilter filter_;
  std::vector<double> units_;  // reused from block to block
};

}  // namespace

std::unique_ptr<FilterEngine> make_filter_engine(const std::string& engine,
                                                 const std::filesystem::path& filter_json,
                                                 int channel) {
  const int channels = model::load_core_config(filter_json).num_channels;
  if (channel < 0 || channel >= channels) {
    throw std::out_of_range(fmt::format("{}: channel {} outside the set's 0 to {}",
                                        filter_json.string(), channel, channels - 1));
  }
  if (engine == "model") return std::make_unique<ModelEngine>(filter_json, channel);
  if (engine == "float") return std::make_unique<FloatEngine>(filter_json, channel);
  if (engine == "rtl") return make_rtl_engine(filter_json, channel);
  throw std::invalid_argument("--engine " + engine + ": valid engines are model, rtl, float");
}

}  // namespace flange::host
