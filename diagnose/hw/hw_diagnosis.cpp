// SPDX-License-Identifier: MIT
#include "hw_diagnosis.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <ostream>
#include <stdexcept>

#include "filter_engine.h"
#include "filter_json.h"
#include "iir_sample_model.h"
#include "input_error.h"
#include "rtl_engine.h"
#include "staged_fixed_point.h"
#include "thesis_filters.h"

namespace flange::diagnose {
namespace fs = std::filesystem;
using host::InputError;

namespace {

constexpr std::size_t kMaxSamples = 10'000'000;
constexpr std::size_t kBlock = 4096;         // samples per round trip to the RTL runner
constexpr double kDivergedFullScales = 1e6;  // a printed filter's output past this has diverged

// The printed coefficients asked for, checked against the design's direct form.
model::SectionCoefficients printed_coefficients(const HwRequest& o,
                                                const model::FloatDesign& design,
                                                std::string& source) {
  const bool given = !o.tf_b.empty() || !o.tf_a.empty();
  if (o.thesis_eq_4_20 && given) {
    throw InputError("--thesis-eq-4-20 and --tf-b/--tf-a: choose one set of printed coefficients");
  }
  std::vector<double> b = o.tf_b, a = o.tf_a;
  source = "--tf-b/--tf-a";
  if (o.thesis_eq_4_20) {
    b = coeffs::thesis_eq_4_20_printed().b;
    a = coeffs::thesis_eq_4_20_printed().a;
    source = coeffs::thesis_eq_4_20_printed().equation + " as printed";
  }
  if (b.empty() || a.empty())
    throw InputError("--tf-b --tf-a: give both the numerator and the denominator");
  const std::string what = o.thesis_eq_4_20 ? "--thesis-eq-4-20" : "--tf-b/--tf-a";
  if (b.size() != design.b.size() || a.size() != design.a.size()) {
    throw InputError(fmt::format(
        "{}: {} numerator and {} denominator coefficients, but the float design in {} (b, a) has "
        "order {} (valid: {} of each){}",
        what, b.size(), a.size(), o.coeffs.string(), design.a.size() - 1, design.a.size(),
        o.thesis_eq_4_20 ? "; eq. 4.20 is the 7th-order vehicle filter: coeffs/vehicle_sos" : ""));
  }
  if (a[0] == 0.0 || !std::isfinite(a[0])) {
    throw InputError(fmt::format("{}: a[0] is {} (valid: a finite non-zero number)", what, a[0]));
  }
  model::SectionCoefficients s;
  for (double v : b) s.b.push_back(v / a[0]);
  for (double v : a) s.a.push_back(v / a[0]);
  s.e = model::error_feedback_words(s.a);
  return s;
}

}  // namespace

HwInputs load_hw_inputs(const HwRequest& o) {
  if (o.coeffs.empty()) throw InputError("--coeffs: required with --hw (a set's filter.json)");
  if (o.samples == 0 || o.samples > kMaxSamples) {
    throw InputError(fmt::format("--samples {}: must lie in [1, {}]", o.samples, kMaxSamples));
  }
  HwInputs in;
  try {
    in.config = model::load_core_config(o.coeffs);
    in.design = model::load_float_design(o.coeffs);
  } catch (const model::FilterJsonError& e) {
    throw InputError(e.what());
  }
  HwStimulusSpec spec;
  spec.kind = o.stimulus;
  spec.samples = o.samples;
  spec.seed = o.seed;
  spec.sample_width = in.config.sample_width;
  spec.fs_hz = in.design.fs_hz;
  spec.fc_hz = in.design.fc_hz.value_or(in.design.fs_hz / 10);
  in.stimulus = make_hw_stimulus(spec);
  return in;
}

HwDiagnosis diagnose_printed(const HwRequest& o, const HwInputs& in) {
  HwDiagnosis d;
  d.mode = "printed";
  const model::SectionCoefficients printed = printed_coefficients(o, in.design, d.printed_source);
  const double a0 = in.design.a[0];
  model::SectionCoefficients exact;
  for (double v : in.design.b) exact.b.push_back(v / a0);
  for (double v : in.design.a) exact.a.push_back(v / a0);
  exact.e = model::error_feedback_words(exact.a);

  GapProblem p;
  p.format = model::staged_format(in.config);
  p.exact = {exact};
  p.quantised = {printed};
  p.candidates = {model::FixedPointEffect::kCoefficients};
  // The real: the printed filter in double precision, until it has plainly diverged.
  model::StagedFixedPoint real(
      p.format, p.exact, p.quantised,
      model::EffectSet::none().with(model::FixedPointEffect::kCoefficients));
  const double limit = kDivergedFullScales * std::ldexp(1.0, in.config.sample_width - 1);
  for (double x : in.stimulus.analog) {
    const double y = real.step(x);
    if (!(std::abs(y) <= limit)) {
      d.diverged_at = p.real.size();
      break;
    }
    p.input.push_back(x);
    p.real.push_back(y);
  }
  if (p.real.empty()) {
    throw std::runtime_error("the printed filter diverges on the first sample; nothing to compare");
  }
  d.input = p.input;
  d.real = p.real;
  d.attribution = attribute_gap(p);
  return d;
}

HwDiagnosis diagnose_rtl(const HwRequest& o, const HwInputs& in, std::ostream& err) {
  HwDiagnosis d;
  d.mode = "rtl";
  for (const char* file : {"iir_coeffs_pkg.sv", "coeffs.mem"}) {
    const fs::path f = fs::absolute(o.coeffs).parent_path() / file;
    if (!fs::is_regular_file(f)) {
      throw InputError(
          fmt::format("{}: missing (it must sit beside {}; regenerate the set with "
                      "flange design)",
                      f.string(), o.coeffs.filename().string()));
    }
  }
  std::unique_ptr<host::FilterEngine> rtl;
  try {
    rtl = host::make_rtl_engine(o.coeffs);
  } catch (const std::exception& e) {
    throw std::runtime_error(
        fmt::format("the Verilated RTL cannot be built or started: {}", e.what()));
  }
  const double full_scale = std::ldexp(1.0, in.config.sample_width - 1);
  // Only the model's words are compared, so its sample-level twin does (equal on every word).
  model::IirSampleModel core(in.config);
  std::vector<double> model_words;
  const std::vector<double>& analog = in.stimulus.analog;
  for (std::size_t start = 0; start < analog.size(); start += kBlock) {
    const std::size_t end = std::min(analog.size(), start + kBlock);
    std::vector<host::EngineSample> block;
    for (std::size_t n = start; n < end; ++n) {
      block.push_back({analog[n] / full_scale, in.stimulus.words[n]});
      model_words.push_back(core.step(in.stimulus.words[n]).sample);
    }
    std::vector<host::EngineOutput> outputs;
    rtl->process(block, outputs);
    for (const host::EngineOutput& y : outputs) d.real.push_back(y.word);
  }
  d.runner_mismatches = rtl->mismatches();
  rtl.reset();
  for (std::size_t n = 0; n < d.real.size(); ++n) {
    if (d.real[n] != model_words[n]) ++d.model_vs_rtl;
  }
  GapProblem p;
  p.format = model::staged_format(in.config);
  p.exact = model::float_sections(in.config, in.design);
  p.quantised = model::rom_sections(in.config);
  p.input = analog;
  p.real = d.real;
  d.input = analog;
  d.attribution = attribute_gap(p);
  const GapStep& all_on = d.attribution.steps.back();
  for (std::size_t n = 0; n < model_words.size(); ++n) {
    if (all_on.output[n] != model_words[n]) ++d.staged_vs_model;
  }
  if (d.model_vs_rtl > 0) {
    err << fmt::format(
        "flange diagnose --hw: the RTL differs from the bit-accurate model on {} "
        "samples; reproduce: flange cosim --coeffs {}\n",
        d.model_vs_rtl, o.coeffs.string());
  }
  return d;
}

}  // namespace flange::diagnose
