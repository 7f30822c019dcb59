// SPDX-License-Identifier: MIT
#include "diagnose_selftest.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>

#include "bench_scenario.h"
#include "diagnosis_detail.h"
#include "effect_classes.h"
#include "parallel_cases.h"
#include "selftest_draw.h"
#include "sensor_twin.h"
#include "series_statistics.h"

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
  recordings.noise_std_v = sim::TwinConfig{}.noise.voltage_std_v;
  return recordings;
}

SelftestScore score_selftest_case(const SelftestCaseSpec& spec, const Diagnosis& diagnosis,
                                  double noise_std_v) {
  SelftestScore score;
  // A partly explained verdict names its effects as found: they are claims too.
  if (diagnosis.status == "explained" || diagnosis.status == "partly explained") {
    for (const EffectFinding& f : diagnosis.effects) score.claimed.push_back(f.name);
  }
  const auto is_true = [&](const std::string& name) {
    return std::any_of(spec.truth.begin(), spec.truth.end(),
                       [&](const sim::EffectSettings& e) { return e.name == name; });
  };
  for (const std::string& name : score.claimed) {
    score.claim_right.push_back(is_true(name));
    score.spurious += is_true(name) ? 0 : 1;
  }
  switch (spec.kind) {
    case SelftestKind::kSingle:
    case SelftestKind::kPair: {
      score.verdict_correct = diagnosis.status == "explained";
      score.top_correct = !score.claimed.empty() && is_true(score.claimed.front());
      score.all_found = std::all_of(spec.truth.begin(), spec.truth.end(), [&](const auto& e) {
        return std::find(score.claimed.begin(), score.claimed.end(), e.name) != score.claimed.end();
      });
      score.bias_type = std::all_of(spec.truth.begin(), spec.truth.end(),
                                    [](const auto& e) { return removable(e.name); });
      break;
    }
    case SelftestKind::kNull:
      score.verdict_correct = diagnosis.status == "none";
      break;
    case SelftestKind::kOutside:
      score.verdict_correct = diagnosis.status == "unexplained";
      break;
  }
  const double before = diagnosis.heldout_rms_before;
  const double after = diagnosis.heldout_rms_after;
  if (before > 0.0) score.shrink_pct = 100.0 * (before - after) / before;
  const double excess_before = rms_above_noise(before, noise_std_v);
  if (excess_before > 0.0) {
    score.excess_shrink_pct = 100.0 * (1.0 - rms_above_noise(after, noise_std_v) / excess_before);
  }
  return score;
}

SelftestSummary summarise_selftest(const std::vector<SelftestCaseResult>& results) {
  SelftestSummary s;
  s.cases = static_cast<int>(results.size());
  double shrink_sum = 0.0, excess_sum = 0.0;
  for (const SelftestCaseResult& r : results) {
    const SelftestScore& score = r.score;
    switch (r.spec.kind) {
      case SelftestKind::kSingle:
      case SelftestKind::kPair:
        ++s.in_library;
        s.top_correct += score.top_correct ? 1 : 0;
        s.all_found += score.all_found ? 1 : 0;
        s.spurious += score.spurious;
        if (score.bias_type) {
          ++s.bias_type;
          shrink_sum += score.shrink_pct;
          excess_sum += score.excess_shrink_pct;
        }
        break;
      case SelftestKind::kNull:
        ++s.null_cases;
        s.null_claims += score.claimed.empty() ? 0 : 1;
        s.null_correct += score.verdict_correct ? 1 : 0;
        break;
      case SelftestKind::kOutside:
        ++s.outside_cases;
        s.outside_claims += score.claimed.empty() ? 0 : 1;
        s.outside_correct += score.verdict_correct ? 1 : 0;
        break;
    }
  }
  if (s.bias_type > 0) {
    s.mean_shrink_pct = shrink_sum / s.bias_type;
    s.mean_excess_shrink_pct = excess_sum / s.bias_type;
  }
  s.top_aim_met = s.in_library == 0 || 10 * s.top_correct >= 9 * s.in_library;
  s.shrink_aim_met = s.bias_type == 0 || s.mean_excess_shrink_pct >= 70.0;
  s.null_aim_met = s.null_claims == 0;
  return s;
}

std::vector<SelftestCaseResult> run_selftest(const SelftestOptions& options) {
  const int count = options.only_case > 0 ? 1 : options.cases;
  std::vector<SelftestCaseResult> results(static_cast<std::size_t>(count));
  run_in_parallel(count, options.jobs, [&](int i) {
    const auto start = std::chrono::steady_clock::now();
    SelftestCaseResult& r = results[static_cast<std::size_t>(i)];
    const int index = options.only_case > 0 ? options.only_case : i + 1;
    r.spec = draw_selftest_case(index, options.seed);
    SelftestRecordings rec = make_selftest_recordings(r.spec, options.duration_s);
    DiagnoseOptions diagnose_options;  // blind: the default twin, noise estimated
    diagnose_options.bootstrap_rounds = options.bootstrap_rounds;
    diagnose_options.seed = options.seed + static_cast<std::uint64_t>(index);
    DiagnosisResult detailed = diagnose_in_detail(rec.calibration, rec.heldout, diagnose_options);
    r.diagnosis = std::move(detailed.diagnosis);
    r.partial = std::move(detailed.detail.partial);
    r.score = score_selftest_case(r.spec, r.diagnosis, rec.noise_std_v);
    if (options.only_case > 0) r.recordings = std::move(rec);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  });
  return results;
}

}  // namespace flange::diagnose
