// SPDX-License-Identifier: MIT
#include "effect_sizing.h"

#include <algorithm>
#include <cmath>

namespace flange::third_reality {
namespace {

constexpr double kLeastNoiseV = 0.002;
constexpr double kMostNoiseV = 0.1;
constexpr int kRedraws = 30;

double quantile_of(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1))];
}

// The RMS of what `draw` alone adds to the ideal twin's gap on the noise-free fitting session.
double added_rms_v(const EffectDraw& draw, const SessionPlan& fit,
                   const std::vector<double>& baseline) {
  const std::vector<double> gap = ideal_twin_gap(render_session(fit, {draw}, false));
  double sum = 0.0;
  for (std::size_t k = 0; k < gap.size(); ++k)
    sum += (gap[k] - baseline[k]) * (gap[k] - baseline[k]);
  return std::sqrt(sum / static_cast<double>(std::max<std::size_t>(gap.size(), 1)));
}

EffectDraw draw_of(const std::string& name, const DrawContext& context, ThirdRandom& random) {
  const ThirdClass& c = third_class(name);
  const std::string& shape =
      c.shapes[static_cast<std::size_t>(random.below(static_cast<int>(c.shapes.size())))];
  return c.draw(shape, context, random);
}

// An effect that sets the noise: redrawn until rms / ratio is a noise in range.
ThirdTruthEffect noise_setting(const std::string& name, const DrawContext& context,
                               ThirdPairSpec& spec, const std::vector<double>& baseline,
                               ThirdRandom& random) {
  const double ratio = random.uniform(kLeastSize, kMostSize);
  ThirdTruthEffect best;
  double best_miss = 1e300;
  for (int attempt = 0; attempt < kRedraws && best_miss > 0.0; ++attempt) {
    const EffectDraw draw = draw_of(name, context, random);
    const double rms = added_rms_v(draw, spec.fit, baseline);
    const double noise = rms / ratio;
    const double miss =
        std::max({0.0, std::log(kLeastNoiseV / noise), std::log(noise / kMostNoiseV)});
    if (miss < best_miss) {
      best_miss = miss;
      best = {draw, rms};
    }
  }
  spec.fit.noise_v = spec.heldout.noise_v =
      std::clamp(best.rms_v / ratio, kLeastNoiseV, kMostNoiseV);
  return best;
}

// An effect with an amplitude, scaled until it adds `target_v`; redrawn when it adds nothing.
ThirdTruthEffect scaled(const std::string& name, const DrawContext& context, const SessionPlan& fit,
                        const std::vector<double>& baseline, double target_v, ThirdRandom& random) {
  ThirdTruthEffect e{draw_of(name, context, random), 0.0};
  for (int attempt = 0; attempt < kRedraws; ++attempt) {
    e.rms_v = added_rms_v(e.draw, fit, baseline);
    if (e.rms_v > 1e-9) break;
    e.draw = draw_of(name, context, random);
  }
  double& amplitude = e.draw.params[e.draw.amplitude_key];
  for (int pass = 0; pass < 8 && std::abs(e.rms_v / target_v - 1.0) > 0.01; ++pass) {
    amplitude *= target_v / std::max(e.rms_v, 1e-12);
    e.rms_v = added_rms_v(e.draw, fit, baseline);
  }
  return e;
}

}  // namespace

DrawContext draw_context(const SessionPlan& fit, const SessionPlan& heldout) {
  const ThirdRecording base = render_session(fit, {}, false);
  DrawContext c;
  c.fs_hz = fit.fs_hz;
  c.duration_s = fit.duration_s;
  const auto [tlo, thi] = std::minmax_element(base.temp_c.begin(), base.temp_c.end());
  c.temp_lo_c = *tlo;
  c.temp_hi_c = *thi;
  const auto [dlo, dhi] = std::minmax_element(base.clearance_mm.begin(), base.clearance_mm.end());
  c.clearance_lo_mm = *dlo;
  c.clearance_hi_mm = *dhi;
  c.voltage_median_v = quantile_of(base.voltage_v, 0.5);
  c.voltage_high_v = quantile_of(base.voltage_v, 0.9);
  c.age_lo_s = fit.start_age_s;
  c.age_hi_s = heldout.start_age_s + heldout.duration_s;
  return c;
}

std::vector<ThirdTruthEffect> sized_effects(const std::vector<std::string>& classes,
                                            ThirdPairSpec& spec, ThirdRandom& random) {
  const DrawContext context = draw_context(spec.fit, spec.heldout);
  const std::vector<double> baseline = ideal_twin_gap(render_session(spec.fit, {}, false));
  std::vector<ThirdTruthEffect> effects;
  for (const std::string& name : classes) {
    if (third_class(name).sets_noise) {
      effects.push_back(noise_setting(name, context, spec, baseline, random));
    }
  }
  for (const std::string& name : classes) {
    if (third_class(name).sets_noise) continue;
    const double target_v = random.uniform(kLeastSize, kMostSize) * spec.fit.noise_v;
    effects.push_back(scaled(name, context, spec.fit, baseline, target_v, random));
  }
  return effects;
}

}  // namespace flange::third_reality
