// SPDX-License-Identifier: MIT
#include "diagnose_selftest.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "bench_scenario.h"
#include "effect_classes.h"
#include "selftest_draw.h"
#include "sensor_twin.h"

namespace flange::diagnose {
namespace {

constexpr int kKindCycle = 10;  // five singles, two pairs, a null, two outside the library
SelftestKind kind_of(int index) {
  const int slot = (index - 1) % kKindCycle;
  if (slot < 5) return SelftestKind::kSingle;
  if (slot < 7) return SelftestKind::kPair;
  if (slot == 7) return SelftestKind::kNull;
  return SelftestKind::kOutside;
}

using Draw = SelftestDraw;

// Parameters of each library effect, drawn as the class table says (EffectClass::selftest_draw).
sim::ParamValues draw_params(const std::string& name, Draw& draw) {
  return effect_class(name).selftest_draw(draw);
}

// The catalogue's effects the self-test draws (those the class table gives a draw), in chain
// order; the tabulated effect, which replays a table, is not among them.
std::vector<std::string> drawable_effects() {
  std::vector<std::string> names;
  for (const sim::EffectSpec& spec : sim::effect_catalogue()) {
    if (effect_class(spec.name).selftest_draw != nullptr) names.push_back(spec.name);
  }
  return names;
}

// Noise-type effects add variance, not a bias the twin could subtract.
bool removable(const std::string& name) {
  return effect_class(name).identification == Identification::kByBias;
}

// Micrometer backlash: the disk follows the micrometer only once the play is taken up, so the
// gap the coil sees lags the reading by half the play, on the side of the last motion.
class Backlash {
 public:
  explicit Backlash(double play_mm) : half_(play_mm / 2) {}
  double follow(double reading_mm) {
    if (!started_) {
      position_ = reading_mm;
      started_ = true;
    }
    position_ = std::clamp(position_, reading_mm - half_, reading_mm + half_);
    return position_;
  }

 private:
  double half_;
  double position_ = 0.0;
  bool started_ = false;
};

RecordingSeries bench_session(const SelftestCaseSpec& spec, const sim::BenchProtocol& protocol,
                              double duration_s, std::uint64_t noise_seed) {
  sim::TwinConfig config;
  config.effects = spec.truth;
  sim::SensorTwin twin(config, noise_seed);
  constexpr double kFsHz = 6.0;  // the thesis's DAQ rate (4.3.1)
  sim::BenchScenario scenario(protocol, kFsHz, duration_s);
  const bool backlash = spec.kind == SelftestKind::kOutside && spec.outside.name == "backlash";
  const bool gain_step = spec.kind == SelftestKind::kOutside && spec.outside.name == "gain_step";
  Backlash mount(backlash ? spec.outside.value : 0.0);
  const double step_at_s = spec.outside.at_fraction * duration_s;
  RecordingSeries series;
  for (std::int64_t i = 0; i < scenario.sample_count(); ++i) {
    sim::TrueState truth = scenario.next();
    const double micrometer_mm = truth.clearance_mm;
    if (backlash) truth.clearance_mm = mount.follow(micrometer_mm);
    const sim::Reading reading = twin.step(truth);
    double voltage = reading.voltage_v;
    if (gain_step && truth.t_s >= step_at_s) {
      voltage = std::clamp(voltage * (1.0 + spec.outside.value), 0.0, 10.0);  // the sensor's rails
    }
    series.t_s.push_back(truth.t_s);
    series.clearance_mm.push_back(micrometer_mm);
    series.temp_c.push_back(reading.temp_c);
    series.voltage_v.push_back(voltage);
  }
  return series;
}

BlindTruth truth_of(const SelftestCaseSpec& spec, double noise_std_v) {
  BlindTruth truth;
  truth.kind = spec.kind;
  for (const sim::EffectSettings& e : spec.truth) truth.classes.push_back(e.name);
  truth.bias_type = std::all_of(spec.truth.begin(), spec.truth.end(),
                                [](const auto& e) { return removable(e.name); });
  truth.noise_std_v = noise_std_v;
  return truth;
}

std::string name_of(const EffectFinding& finding) { return finding.name; }

std::string describe_truth(const SelftestCaseSpec& spec) {
  if (spec.kind == SelftestKind::kNull) return "(nothing)";
  if (spec.kind == SelftestKind::kOutside) return spec.outside.describe();
  std::string text;
  for (const sim::EffectSettings& e : spec.truth) {
    std::string params;
    for (const auto& [key, value] : e.params) {
      params += fmt::format("{}{}={:.3g}", params.empty() ? "" : ", ", key, value);
    }
    text += fmt::format("{}{}({})", text.empty() ? "" : " + ", e.name, params);
  }
  return text;
}

nlohmann::json truth_json(const SelftestCaseSpec& spec) {
  nlohmann::json truth = nlohmann::json::array();
  for (const sim::EffectSettings& e : spec.truth) {
    truth.push_back({{"name", e.name}, {"params", e.params}});
  }
  nlohmann::json j = {
      {"case", spec.index}, {"kind", selftest_kind_name(spec.kind)}, {"truth", truth}};
  if (spec.kind == SelftestKind::kOutside) {
    j["outside"] = {{"name", spec.outside.name},
                    {"value", spec.outside.value},
                    {"at_fraction", spec.outside.at_fraction}};
  }
  return j;
}

double twin_noise_std_v() { return sim::TwinConfig{}.noise.voltage_std_v; }

class TwinReality : public BlindReality<SelftestCaseSpec, SelftestRecordings> {
 public:
  SelftestCaseSpec draw(int index, const SelftestOptions& options) const override {
    return draw_selftest_case(index, options.seed);
  }
  SelftestRecordings record(const SelftestCaseSpec& spec,
                            const SelftestOptions& options) const override {
    return make_selftest_recordings(spec, options.duration_s);
  }
  BlindSessions as_recordings(const SelftestCaseSpec&,
                              const SelftestRecordings& recordings) const override {
    return {recordings.calibration, recordings.heldout};
  }
  BlindScore score(const SelftestCaseSpec& spec, const BlindOutcome& outcome,
                   const SelftestRecordings& recordings) const override {
    return score_blind(truth_of(spec, recordings.noise_std_v), outcome.diagnosis, outcome.partial,
                       name_of);
  }
  BlindRow row(const SelftestCaseSpec& spec) const override {
    BlindRow row;
    row.index = spec.index;
    row.truth = truth_of(spec, twin_noise_std_v());
    row.kind_name = selftest_kind_name(spec.kind);
    row.truth_text = describe_truth(spec);
    row.noise_v = row.truth.noise_std_v;
    row.truth_json = truth_json(spec);
    return row;
  }
  // The aims: >= 90 % correct top effect, >= 70 % mean held-out shrink (of the gap
  // above the noise) for bias-type effects, no effect claimed on a null case.
  BlindAims aims() const override { return {90, 70.0, false, 0}; }
  std::vector<std::string> class_names() const override { return {}; }
};

}  // namespace

const char* selftest_kind_name(SelftestKind kind) {
  switch (kind) {
    case SelftestKind::kSingle:
      return "single";
    case SelftestKind::kPair:
      return "pair";
    case SelftestKind::kNull:
      return "null";
    case SelftestKind::kOutside:
      return "outside";
  }
  return "?";
}

std::string OutsideEffect::describe() const {
  if (name == "backlash") return fmt::format("backlash(play_mm={:.3g})", value);
  if (name == "gain_step")
    return fmt::format("gain_step(change={:+.3g}, at={:.2g} of the session)", value, at_fraction);
  return name;
}

SelftestCaseSpec draw_selftest_case(int index, std::uint64_t seed) {
  SelftestCaseSpec spec;
  spec.index = index;
  spec.kind = kind_of(index);
  Draw draw(seed * 1000003u + static_cast<std::uint64_t>(index));
  spec.noise_seed = draw.seed();
  const std::vector<std::string> catalogue = drawable_effects();
  const int n = static_cast<int>(catalogue.size());
  std::vector<int> chosen;
  if (spec.kind == SelftestKind::kSingle || spec.kind == SelftestKind::kPair) {
    chosen.push_back(draw.index(n));
    if (spec.kind == SelftestKind::kPair) {
      int second = draw.index(n - 1);
      if (second >= chosen.front()) ++second;
      chosen.push_back(second);
    }
    std::sort(chosen.begin(), chosen.end());  // the twin runs effects in chain order
    for (int c : chosen) {
      const std::string& name = catalogue[static_cast<std::size_t>(c)];
      spec.truth.push_back(
          sim::make_effect_settings(name, draw_params(name, draw), "selftest case"));
    }
  } else if (spec.kind == SelftestKind::kOutside) {
    if (draw.index(2) == 0) {
      spec.outside = {"backlash", draw.uniform(0.15, 0.5), 0.0};
    } else {
      spec.outside = {"gain_step", draw.signed_magnitude(0.04, 0.10), draw.uniform(0.3, 0.7)};
    }
  }
  return spec;
}

SelftestRecordings make_selftest_recordings(const SelftestCaseSpec& spec, double duration_s) {
  sim::BenchProtocol first;
  // The held-out session: another day on the same bench, a little warmer, blower off earlier.
  sim::BenchProtocol second = first;
  second.room_c += 1.5;
  second.blower_off_s -= 100.0;
  const double duration = duration_s > 0.0 ? duration_s : first.duration_s;
  SelftestRecordings recordings;
  recordings.calibration = bench_session(spec, first, duration, spec.noise_seed);
  recordings.heldout = bench_session(spec, second, duration, spec.noise_seed + 1);
  recordings.calibration.path = fmt::format("selftest case {} (calibration)", spec.index);
  recordings.heldout.path = fmt::format("selftest case {} (held-out)", spec.index);
  recordings.noise_std_v = twin_noise_std_v();
  return recordings;
}

SelftestScore score_selftest_case(const SelftestCaseSpec& spec, const Diagnosis& diagnosis,
                                  double noise_std_v) {
  return score_blind(truth_of(spec, noise_std_v), diagnosis, {}, name_of);
}

const BlindReality<SelftestCaseSpec, SelftestRecordings>& twin_reality() {
  static const TwinReality reality;
  return reality;
}

SelftestSummary summarise_selftest(const std::vector<SelftestCaseResult>& results) {
  return summarise_blind(twin_reality(), results);
}

std::vector<SelftestCaseResult> run_selftest(const SelftestOptions& options) {
  return run_blind_check(twin_reality(), options);
}

}  // namespace flange::diagnose
