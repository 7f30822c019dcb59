// SPDX-License-Identifier: MIT
// Factoring a filter into second-order sections and spreading its gain over them.
#pragma once

#include <array>
#include <vector>

#include "butterworth.h"

namespace flange::coeffs {

// One section: b0 + b1 z^-1 + b2 z^-2 over a0 + a1 z^-1 + a2 z^-2, with a0 = 1. A first-order
// section has b2 = a2 = 0.
struct Section {
  std::array<double, 3> b{};
  std::array<double, 3> a{};
};

// Sections with unit-leading numerators, pole pairs matched with their nearest zeros and
// ordered so that the poles nearest the unit circle come last: scipy.signal.zpk2sos with
// pairing 'nearest', before its gain goes into the first section. Complex roots must come in
// conjugate pairs.
std::vector<Section> pair_sections_nearest(const Zpk& zpk);

// A cascade whose gain is spread by L-infinity scaling.
struct ScaledCascade {
  std::vector<Section> sections;
  // Gain not placed in the sections because it would lift the last section's peak above 1;
  // the host applies it. 1.0 for a low-pass Butterworth filter.
  double leftover_gain = 1.0;
};

// Spreads `gain` over `sections` so that the magnitude of the cumulative response after every
// section peaks at exactly 1 (L-infinity scaling): no section output exceeds full scale for a
// full-scale sinusoid. The last section carries the rest of the gain up to that same limit.
ScaledCascade scale_cascade_linf(std::vector<Section> sections, double gain);

// Peak over [0, pi] of |prod_k H_k(e^{j omega})| for the first `count` sections.
double cumulative_peak_magnitude(const std::vector<Section>& sections, std::size_t count);

}  // namespace flange::coeffs
