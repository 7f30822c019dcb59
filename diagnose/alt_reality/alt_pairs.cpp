// SPDX-License-Identifier: MIT
#include "alt_pairs.h"

#include <algorithm>
#include <cmath>

#include "alt_classes.h"
#include "alt_sensor.h"

namespace flange::alt_reality {
namespace {

constexpr int kCycle = 10;
constexpr int kSinglesPerCycle = 6;
constexpr double kSecondsPerDay = 86400.0;
constexpr double kLowestNoiseV = 0.01;

AltPairKind kind_of(int index) {
  const int slot = (index - 1) % kCycle;
  if (slot < kSinglesPerCycle) return AltPairKind::kSingle;
  if (slot == 6) return AltPairKind::kDouble;
  if (slot == 8) return AltPairKind::kOutside;
  return AltPairKind::kNull;
}

std::vector<std::string> classes_of(int index, std::uint64_t seed, AltPairKind kind,
                                    AltRandom& random) {
  const auto& classes = alt_classes();
  const int n = static_cast<int>(classes.size());
  if (kind == AltPairKind::kSingle) {
    const int single = (index - 1) / kCycle * kSinglesPerCycle + (index - 1) % kCycle;
    return {classes[static_cast<std::size_t>((single + static_cast<int>(seed % 11)) % n)].name};
  }
  if (kind == AltPairKind::kDouble) {
    const int first = random.index(n);
    int second = random.index(n - 1);
    if (second >= first) ++second;
    const int lo = std::min(first, second), hi = std::max(first, second);  // chain order
    return {classes[static_cast<std::size_t>(lo)].name, classes[static_cast<std::size_t>(hi)].name};
  }
  if (kind == AltPairKind::kOutside) return {"outside"};
  return {};
}

// The two sessions: one family of protocols, each session its own parameters.
void draw_sessions(AltPairSpec& spec, double duration_cap_s, AltRandom& random) {
  constexpr double kRates[3] = {6.0, 7.0, 9.0};
  const double fs_hz = kRates[random.index(3)];
  const auto heating = static_cast<HeatingKind>(random.index(kHeatingKinds));
  const auto micrometer = static_cast<MicrometerKind>(random.index(kMicrometerKinds));
  const double noise_v = random.log_uniform(kLowestNoiseV, 0.1);
  const double fit_age_s = random.log_uniform(0.02, 20.0) * kSecondsPerDay;
  const double resolution_c = random.index(2) == 0 ? 0.01 : 0.1;
  const double thermocouple_noise_c = random.uniform(0.02, 0.2);
  double duration_s = random.uniform(3600.0, 6600.0);
  for (SessionPlan* plan : {&spec.fit, &spec.heldout}) {
    if (duration_cap_s > 0.0) duration_s = std::min(duration_s, duration_cap_s);
    plan->fs_hz = fs_hz;
    plan->duration_s = duration_s;
    plan->heating = draw_heating(heating, duration_s, random);
    plan->micrometer = draw_micrometer(micrometer, duration_s, random);
    plan->noise_v = noise_v;
    plan->thermocouple_noise_c = thermocouple_noise_c;
    plan->thermocouple_resolution_c = resolution_c;
    plan->noise_seed = static_cast<std::uint64_t>(random.sub_seed());
    duration_s *= random.uniform(0.8, 1.0);  // the held-out session is a little shorter
  }
  spec.fit.start_age_s = fit_age_s;
  spec.heldout.start_age_s =
      fit_age_s + spec.fit.duration_s + random.log_uniform(0.2, 5.0) * kSecondsPerDay;
}

// What an ideal twin sees of a noise-free session: the recorded voltage less the ideal sensor's
// at the recorded clearance and temperature (a late temperature channel shows here too).
std::vector<double> ideal_gap(const AltRecording& r) {
  std::vector<double> gap(r.size());
  for (std::size_t i = 0; i < r.size(); ++i) {
    gap[i] = r.voltage_v[i] - ideal_sensor_voltage(r.clearance_mm[i], r.temp_c[i]);
  }
  return gap;
}

// The RMS of what `draw` alone adds to that gap on the fitting session.
double effect_rms_v(const AltEffectDraw& draw, const SessionPlan& fit,
                    const std::vector<double>& baseline_gap) {
  const std::vector<double> gap = ideal_gap(render_session(fit, {draw}, false));
  double sum = 0.0;
  for (std::size_t i = 0; i < gap.size(); ++i) sum += std::pow(gap[i] - baseline_gap[i], 2);
  return gap.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(gap.size()));
}

AltEffectDraw draw_shape_of(const std::string& class_name, const AltPairSpec& spec,
                            AltRandom& random) {
  const AltClass& c = alt_class(class_name);
  const auto shape = static_cast<std::size_t>(random.index(static_cast<int>(c.shapes.size())));
  const DrawContext context{spec.fit.fs_hz, spec.fit.start_age_s, spec.fit.duration_s};
  return c.draw(c.shapes[shape], context, random);
}

// A shape without an amplitude (lags, skews, compression), redrawn up to ten times until the
// effect reaches the noise; the largest draw is kept.
TruthEffect redrawn_to_the_noise(const std::string& class_name, const AltPairSpec& spec,
                                 const std::vector<double>& baseline_gap, AltRandom& random) {
  TruthEffect best{draw_shape_of(class_name, spec, random), 0.0};
  best.rms_v = effect_rms_v(best.draw, spec.fit, baseline_gap);
  for (int attempt = 1; attempt < 10 && best.rms_v < spec.fit.noise_v; ++attempt) {
    AltEffectDraw again =
        alt_class(class_name)
            .draw(best.draw.shape, {spec.fit.fs_hz, spec.fit.start_age_s, spec.fit.duration_s},
                  random);
    const double rms = effect_rms_v(again, spec.fit, baseline_gap);
    if (rms > best.rms_v) best = {again, rms};
  }
  return best;
}

// A shape with an amplitude, scaled so that its RMS is 1 to 5 times the noise (log-uniform).
TruthEffect scaled_to_the_noise(AltEffectDraw draw, const AltPairSpec& spec,
                                const std::vector<double>& baseline_gap, AltRandom& random) {
  const double target_v = random.log_uniform(1.0, 5.0) * spec.fit.noise_v;
  const double unit_rms = effect_rms_v(draw, spec.fit, baseline_gap);
  if (unit_rms > 0.0) draw.params[draw.amplitude_key] *= target_v / unit_rms;
  return {draw, effect_rms_v(draw, spec.fit, baseline_gap)};
}

// Sizes the pair's effects (see draw_alt_pair): the unscalable ones first; where one stays
// below the noise even so, the pair's noise is lowered to it (not below 0.01 V); then the
// scalable ones against that noise.
void size_effects(const std::vector<std::string>& classes, AltPairSpec& spec, AltRandom& random) {
  const std::vector<double> baseline_gap = ideal_gap(render_session(spec.fit, {}, false));
  std::vector<AltEffectDraw> scalable;
  for (const std::string& name : classes) {
    AltEffectDraw draw = draw_shape_of(name, spec, random);
    if (!draw.amplitude_key.empty()) {
      scalable.push_back(draw);
    } else if (name == "quantisation" || name == "outside") {
      spec.truth.push_back({draw, effect_rms_v(draw, spec.fit, baseline_gap)});
    } else {
      spec.truth.push_back(redrawn_to_the_noise(name, spec, baseline_gap, random));
      const double noise_v = std::clamp(spec.truth.back().rms_v, kLowestNoiseV, spec.fit.noise_v);
      spec.fit.noise_v = spec.heldout.noise_v = noise_v;
    }
  }
  for (const AltEffectDraw& draw : scalable) {
    spec.truth.push_back(scaled_to_the_noise(draw, spec, baseline_gap, random));
  }
  const auto& order = alt_classes();
  const auto rank = [&](const TruthEffect& e) {
    for (std::size_t i = 0; i < order.size(); ++i) {
      if (order[i].name == e.draw.class_name) return i;
    }
    return order.size();  // outside: last
  };
  std::sort(spec.truth.begin(), spec.truth.end(),
            [&](const auto& a, const auto& b) { return rank(a) < rank(b); });
}

}  // namespace

const char* alt_pair_kind_name(AltPairKind kind) {
  switch (kind) {
    case AltPairKind::kSingle:
      return "single";
    case AltPairKind::kDouble:
      return "double";
    case AltPairKind::kNull:
      return "null";
    case AltPairKind::kOutside:
      return "outside";
  }
  return "?";
}

AltPairSpec draw_alt_pair(int index, std::uint64_t seed, double duration_s) {
  AltPairSpec spec;
  spec.index = index;
  spec.seed = seed;
  spec.kind = kind_of(index);
  AltRandom random(seed * 0x9E3779B97F4A7C15ULL + static_cast<std::uint64_t>(index) * 7919u);
  const std::vector<std::string> classes = classes_of(index, seed, spec.kind, random);
  draw_sessions(spec, duration_s, random);
  if (classes.empty()) return spec;
  size_effects(classes, spec, random);
  return spec;
}

AltPair render_alt_pair(const AltPairSpec& spec) {
  std::vector<AltEffectDraw> draws;
  for (const TruthEffect& e : spec.truth) draws.push_back(e.draw);
  return {render_session(spec.fit, draws, true), render_session(spec.heldout, draws, true)};
}

}  // namespace flange::alt_reality
