// SPDX-License-Identifier: MIT
#include "moderated_spread.h"

#include <algorithm>
#include <boost/math/special_functions/digamma.hpp>
#include <boost/math/special_functions/trigamma.hpp>
#include <cmath>
#include <limits>

namespace flange::host {
namespace {

bool in_prior(const SerialSpread& spread) { return spread.blocks > 0 && spread.inflation > 0.0; }

// log s - E[log chi2_d / d]: an unbiased estimate of log s0 when s ~ s0 chi2_d / d.
double centred_log(const SerialSpread& spread) {
  const double half = spread.dof / 2.0;
  return std::log(spread.inflation) - boost::math::digamma(half) + std::log(half);
}

}  // namespace

double inverse_trigamma(double x) {
  // Smyth's start and Newton steps on 1 / trigamma(y), which is nearly linear in y.
  if (x > 1e7) return 1.0 / std::sqrt(x);
  if (x < 1e-6) return 1.0 / x;
  double y = 0.5 + 1.0 / x;
  for (int step = 0; step < 50; ++step) {
    const double tri = boost::math::trigamma(y);
    const double change = tri * (1.0 - tri / x) / boost::math::polygamma(2, y);
    y += change;
    if (-change / y < 1e-8) break;
  }
  return y;
}

InflationPrior inflation_prior(const std::vector<SerialSpread>& spreads) {
  std::vector<double> z;
  double expected_spread = 0.0;  // the logarithms' variance their own dof explain
  for (const SerialSpread& spread : spreads) {
    if (!in_prior(spread)) continue;
    z.push_back(centred_log(spread));
    expected_spread += boost::math::trigamma(spread.dof / 2.0);
  }
  if (static_cast<int>(z.size()) < kMinPriorWheels) return {};
  const auto n = static_cast<double>(z.size());
  double mean = 0.0;
  for (const double v : z) mean += v;
  mean /= n;
  double variance = 0.0;
  for (const double v : z) variance += (v - mean) * (v - mean);
  variance /= n - 1.0;
  const double excess = variance - expected_spread / n;
  if (!(excess > 0.0)) return {std::numeric_limits<double>::infinity(), std::exp(mean)};
  const double d0 = 2.0 * inverse_trigamma(excess);
  return {d0, std::exp(mean + boost::math::digamma(d0 / 2.0) - std::log(d0 / 2.0))};
}

SerialSpread moderated_spread(const SerialSpread& own, const InflationPrior& prior,
                              double fit_rate_se) {
  if (!(prior.dof > 0.0) || own.blocks == 0) return own;
  SerialSpread spread = own;
  const double d = own.dof;
  const bool pooled = std::isinf(prior.dof) || prior.dof + d >= kMaxModeratedDof;
  spread.inflation =
      pooled ? prior.inflation : (prior.dof * prior.inflation + d * own.inflation) / (prior.dof + d);
  spread.rate_se = std::sqrt(spread.inflation) * fit_rate_se;
  // Rounded down: an interval a shade wider rather than narrower than its level.
  spread.dof = pooled ? kMaxModeratedDof : static_cast<int>(std::floor(prior.dof + d));
  return spread;
}

}  // namespace flange::host
