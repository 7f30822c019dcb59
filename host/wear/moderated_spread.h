// SPDX-License-Identifier: MIT
// Each wheel's jackknife steadied by the fleet's: empirical-Bayes moderation of the variance
// (Smyth 2004, the "moderated t"). A wheel's jackknife has only B - 1 degrees of freedom, so its
// variance scatters widely about the truth: mostly too large, sometimes far too small. The wheels
// of one estimate share the estimator's design, the fleet's season and its routes, so their
// inflations (the jackknife's variance over the least-squares one) come from one distribution.
// Fitted to the inflations as a scaled inverse chi-square prior with d0 degrees of freedom about
// s0 (from the mean and the spread of their logarithms, the spread left after what each wheel's
// own B - 1 degrees of freedom explain), each wheel's inflation becomes
//   (d0 s0 + d s) / (d0 + d)
// and its rate over the standard error from it is Student t with d0 + d degrees of freedom. Where
// the wheels' inflations differ by more than their own few degrees of freedom explain, d0 is small
// and each wheel keeps its own; where they differ by less, d0 is large and they are pooled.
#pragma once

#include <vector>

#include "block_jackknife.h"

namespace flange::host {

// Caps the moderated degrees of freedom (d0 infinite: the inflations do not differ beyond their
// own chance, so the prior alone is used; Student t at 1000 degrees of freedom is the normal's).
inline constexpr int kMaxModeratedDof = 1000;
// Fewer jackknifed wheels than this: no prior (each wheel keeps its own jackknife).
inline constexpr int kMinPriorWheels = 4;

struct InflationPrior {
  double dof = 0.0;        // d0 (0: no prior; +inf: pooled)
  double inflation = 1.0;  // s0: the typical inflation
};

// From the jackknifed wheels' spreads (those with blocks 0 or inflation 0 left out).
InflationPrior inflation_prior(const std::vector<SerialSpread>& spreads);

// `own` moderated by `prior`; `fit_rate_se` is the least-squares standard error `own` inflates.
// Unchanged when the prior is none or `own` has no jackknife.
SerialSpread moderated_spread(const SerialSpread& own, const InflationPrior& prior,
                              double fit_rate_se);

// The inverse of the trigamma function (x > 0), by Newton's method as in Smyth (2004).
double inverse_trigamma(double x);

}  // namespace flange::host
