// SPDX-License-Identifier: MIT
#include "hw_gap.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>

#include "polynomial.h"

namespace flange::diagnose {

PoleCheck check_poles(const std::vector<model::SectionCoefficients>& sections) {
  PoleCheck check;
  for (const model::SectionCoefficients& s : sections) {
    // a[0] z^M + a[1] z^(M-1) + ... + a[M]: highest power first, as polynomial_roots wants.
    std::vector<double> denominator = s.a;
    while (denominator.size() > 1 && denominator.back() == 0.0) {
      denominator.pop_back();  // a pole at z = 0 per trailing zero
    }
    if (denominator.size() < 2) continue;
    for (const coeffs::Complex& pole : coeffs::polynomial_roots(denominator)) {
      const double r = std::abs(pole);
      check.max_radius = std::max(check.max_radius, r);
      if (r >= 1.0) ++check.outside;
    }
  }
  return check;
}

namespace {

std::vector<double> run(const GapProblem& p, model::EffectSet effects) {
  model::StagedFixedPoint filter(p.format, p.exact, p.quantised, effects);
  std::vector<double> y;
  y.reserve(p.input.size());
  for (double x : p.input) y.push_back(filter.step(x));
  return y;
}

GapFigures figures(const std::vector<double>& real, const std::vector<double>& model,
                   const std::vector<double>& reference) {
  GapFigures f;
  double energy = 0.0, signal = 0.0;
  for (std::size_t n = 0; n < real.size(); ++n) {
    const double gap = real[n] - model[n];
    energy += gap * gap;
    signal += reference[n] * reference[n];
    f.max_lsb = std::max(f.max_lsb, std::abs(gap));
    if (gap != 0.0) ++f.differing;
  }
  f.rms_lsb = std::sqrt(energy / static_cast<double>(real.size()));
  if (energy > 0.0 && signal > 0.0) f.snr_db = 10.0 * std::log10(signal / energy);
  return f;
}

}  // namespace

GapAttribution attribute_gap(const GapProblem& problem) {
  if (problem.input.empty() || problem.input.size() != problem.real.size()) {
    throw std::invalid_argument("attribute_gap: input and real output need the same length >= 1");
  }
  GapAttribution result;
  GapStep start;
  start.effects = model::EffectSet::none();
  start.output = run(problem, start.effects);
  const std::vector<double> reference = start.output;
  start.gap = figures(problem.real, start.output, reference);
  start.poles = check_poles(problem.exact);
  if (!start.poles.stable()) result.unstable_step = 0;
  result.steps.push_back(std::move(start));

  std::vector<model::FixedPointEffect> remaining = problem.candidates;
  while (!remaining.empty()) {
    const GapStep& before = result.steps.back();
    std::optional<GapStep> best;
    std::size_t best_index = 0;
    for (std::size_t i = 0; i < remaining.size(); ++i) {
      GapStep step;
      step.added = remaining[i];
      step.effects = before.effects.with(remaining[i]);
      step.output = run(problem, step.effects);
      step.gap = figures(problem.real, step.output, reference);
      if (!best || step.gap.rms_lsb < best->gap.rms_lsb) {
        best = std::move(step);
        best_index = i;
      }
    }
    remaining.erase(remaining.begin() + static_cast<std::ptrdiff_t>(best_index));
    const double was = before.gap.rms_lsb;
    best->changed = best->output != before.output;
    best->shrink_pct = was > 0.0 ? 100.0 * (was - best->gap.rms_lsb) / was : 0.0;
    best->poles =
        check_poles(best->effects.has(model::FixedPointEffect::kCoefficients) ? problem.quantised
                                                                              : problem.exact);
    if (!best->poles.stable() && !result.unstable_step) {
      result.unstable_step = result.steps.size();
    }
    result.steps.push_back(std::move(*best));
  }
  return result;
}

}  // namespace flange::diagnose
