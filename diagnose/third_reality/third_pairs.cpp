// SPDX-License-Identifier: MIT
#include "third_pairs.h"

#include <algorithm>

#include "effect_sizing.h"
#include "mains_wave.h"
#include "third_classes.h"

namespace flange::third_reality {
namespace {

constexpr int kCycle = 10;
constexpr int kSinglesPerCycle = 4;
constexpr double kSecondsPerDay = 86400.0;

ThirdPairKind kind_of(int index, int& effects) {
  const int slot = (index - 1) % kCycle;
  effects = slot < kSinglesPerCycle ? 1 : slot < 6 ? 2 : slot == 6 ? 3 : slot == 8 ? 1 : 0;
  if (slot < kSinglesPerCycle) return ThirdPairKind::kSingle;
  if (slot < 7) return ThirdPairKind::kMulti;
  return slot == 8 ? ThirdPairKind::kOutside : ThirdPairKind::kNull;
}

std::size_t chain_rank(const std::string& name) {
  const auto& order = third_classes();
  for (std::size_t i = 0; i < order.size(); ++i) {
    if (order[i].name == name) return i;
  }
  return order.size();  // outside: last
}

std::vector<std::string> classes_of(int index, std::uint64_t seed, ThirdPairKind kind, int count,
                                    ThirdRandom& random) {
  const auto& classes = third_classes();
  const int n = static_cast<int>(classes.size());
  if (kind == ThirdPairKind::kOutside) return {"outside"};
  if (kind == ThirdPairKind::kSingle) {
    const int single = (index - 1) / kCycle * kSinglesPerCycle + (index - 1) % kCycle;
    return {classes[static_cast<std::size_t>((single + static_cast<int>(seed % 11)) % n)].name};
  }
  std::vector<std::string> drawn;
  while (static_cast<int>(drawn.size()) < count) {
    const std::string& name = classes[static_cast<std::size_t>(random.below(n))].name;
    const bool twice = std::find(drawn.begin(), drawn.end(), name) != drawn.end();
    const bool second_noise_setter =
        third_class(name).sets_noise && std::any_of(drawn.begin(), drawn.end(), [](const auto& d) {
          return third_class(d).sets_noise;
        });
    if (!twice && !second_noise_setter) drawn.push_back(name);
  }
  std::sort(drawn.begin(), drawn.end(),
            [](const auto& a, const auto& b) { return chain_rank(a) < chain_rank(b); });
  return drawn;
}

double draw_rate(bool with_mains, ThirdRandom& random) {
  constexpr double kLow[] = {6.0, 7.0, 8.0, 9.0, 10.0};
  constexpr double kHigh[] = {12.5, 20.0, 25.0, 50.0, 100.0};
  while (true) {
    const double fs = random.chance(0.6) ? kLow[random.below(5)] : kHigh[random.below(5)];
    ThirdRandom probe(1);
    if (!with_mains || usable_mains_hz(fs, probe) > 0.0) return fs;
  }
}

// The two sessions: one kind of heating and of micrometer, each session its own parameters.
void draw_sessions(ThirdPairSpec& spec, bool with_mains, double cap_s, ThirdRandom& random) {
  const double fs_hz = draw_rate(with_mains, random);
  const auto heating = static_cast<HeatingKind>(random.below(kHeatingKinds));
  const auto micrometer = static_cast<MicrometerKind>(random.below(kMicrometerKinds));
  const double noise_v = random.log_uniform(0.005, 0.08);
  const double thermocouple_noise_c = random.uniform(0.02, 0.15);
  const double step_c = random.chance(0.5) ? 0.01 : 0.1;
  double duration_s = random.uniform(2400.0, 5400.0);
  for (SessionPlan* plan : {&spec.fit, &spec.heldout}) {
    if (cap_s > 0.0) duration_s = std::min(duration_s, cap_s);
    plan->fs_hz = fs_hz;
    plan->duration_s = duration_s;
    plan->heating = draw_heating_plan(heating, duration_s, random);
    plan->micrometer = draw_micrometer_plan(micrometer, duration_s, random);
    plan->logger = draw_logger_plan(fs_hz, random);
    plan->noise_v = noise_v;
    plan->thermocouple_noise_c = thermocouple_noise_c;
    plan->thermocouple_step_c = step_c;
    plan->noise_seed = static_cast<std::uint64_t>(random.child_seed());
    duration_s *= random.uniform(0.75, 1.0);  // the held-out session is a little shorter
  }
  spec.fit.start_age_s = random.log_uniform(0.02, 30.0) * kSecondsPerDay;
  spec.heldout.start_age_s =
      spec.fit.start_age_s + spec.fit.duration_s + random.log_uniform(0.2, 5.0) * kSecondsPerDay;
}

}  // namespace

const char* third_pair_kind_name(ThirdPairKind kind) {
  switch (kind) {
    case ThirdPairKind::kSingle:
      return "single";
    case ThirdPairKind::kMulti:
      return "multiple";
    case ThirdPairKind::kNull:
      return "null";
    case ThirdPairKind::kOutside:
      return "outside";
  }
  return "?";
}

ThirdPairSpec draw_third_pair(int index, std::uint64_t seed, double duration_s) {
  ThirdPairSpec spec;
  spec.index = index;
  spec.seed = seed;
  int count = 0;
  spec.kind = kind_of(index, count);
  ThirdRandom random(seed * 0xBF58476D1CE4E5B9ULL + static_cast<std::uint64_t>(index) * 104729u);
  const std::vector<std::string> classes = classes_of(index, seed, spec.kind, count, random);
  const bool with_mains =
      std::find(classes.begin(), classes.end(), "mains_pickup") != classes.end();
  draw_sessions(spec, with_mains, duration_s, random);
  if (classes.empty()) return spec;
  spec.truth = sized_effects(classes, spec, random);
  std::sort(spec.truth.begin(), spec.truth.end(), [](const auto& a, const auto& b) {
    return chain_rank(a.draw.class_name) < chain_rank(b.draw.class_name);
  });
  return spec;
}

ThirdPair render_third_pair(const ThirdPairSpec& spec) {
  std::vector<EffectDraw> draws;
  for (const ThirdTruthEffect& e : spec.truth) draws.push_back(e.draw);
  return {render_session(spec.fit, draws, true), render_session(spec.heldout, draws, true)};
}

}  // namespace flange::third_reality
