// SPDX-License-Identifier: MIT
#include "second_order_sections.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace flange::coeffs {

namespace {

bool is_real(const Complex& value) { return value.imag() == 0.0; }

// Keeps one root of each conjugate pair (the one with positive imaginary part) followed by the
// real roots, as scipy's _cplxreal does; roots within rounding of the real axis become real.
std::vector<Complex> upper_half_then_real(const std::vector<Complex>& roots) {
  std::vector<Complex> complex_part;
  std::vector<Complex> real_part;
  for (const Complex& root : roots) {
    const double tolerance = 100.0 * std::numeric_limits<double>::epsilon() * std::abs(root);
    if (std::abs(root.imag()) <= tolerance) {
      real_part.emplace_back(root.real(), 0.0);
    } else if (root.imag() > 0.0) {
      complex_part.push_back(root);
    }
  }
  auto by_real_then_imag = [](const Complex& x, const Complex& y) {
    return x.real() != y.real() ? x.real() < y.real() : std::abs(x.imag()) < std::abs(y.imag());
  };
  std::stable_sort(complex_part.begin(), complex_part.end(), by_real_then_imag);
  std::stable_sort(real_part.begin(), real_part.end(), by_real_then_imag);
  complex_part.insert(complex_part.end(), real_part.begin(), real_part.end());
  return complex_part;
}

enum class Kind { kAny, kReal, kComplex };

// Index of the root in `from` nearest to `to` among those of the given kind.
std::size_t nearest_index(const std::vector<Complex>& from, const Complex& to, Kind kind) {
  std::size_t best = from.size();
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < from.size(); ++i) {
    if (kind == Kind::kReal && !is_real(from[i])) continue;
    if (kind == Kind::kComplex && is_real(from[i])) continue;
    const double distance = std::abs(from[i] - to);
    if (distance < best_distance) {
      best_distance = distance;
      best = i;
    }
  }
  if (best == from.size()) throw std::logic_error("pair_sections_nearest: no root of that kind");
  return best;
}

Complex take(std::vector<Complex>& roots, std::size_t index) {
  const Complex value = roots[index];
  roots.erase(roots.begin() + static_cast<std::ptrdiff_t>(index));
  return value;
}

std::size_t count_real(const std::vector<Complex>& roots) {
  return static_cast<std::size_t>(std::count_if(roots.begin(), roots.end(), is_real));
}

// A section from up to two zeros and two poles; a complex root stands for itself and its
// conjugate.
Section make_section(std::vector<Complex> zeros, std::vector<Complex> poles) {
  auto expand = [](std::vector<Complex> roots) {
    if (roots.size() == 1 && !is_real(roots[0])) roots.push_back(std::conj(roots[0]));
    while (roots.size() < 2) roots.emplace_back(0.0, 0.0);
    return poly_from_roots(roots);
  };
  const std::vector<double> b = expand(std::move(zeros));
  const std::vector<double> a = expand(std::move(poles));
  return Section{{b[0], b[1], b[2]}, {a[0], a[1], a[2]}};
}

}  // namespace

std::vector<Section> pair_sections_nearest(const Zpk& zpk) {
  std::vector<Complex> zeros = zpk.zeros;
  std::vector<Complex> poles = zpk.poles;
  while (poles.size() < zeros.size()) poles.emplace_back(0.0, 0.0);
  while (zeros.size() < poles.size()) zeros.emplace_back(0.0, 0.0);
  const std::size_t section_count = (poles.size() + 1) / 2;
  if (poles.size() % 2 == 1) {
    // An odd order gets a pole and a zero at the origin: its real pole becomes a first-order
    // section.
    poles.emplace_back(0.0, 0.0);
    zeros.emplace_back(0.0, 0.0);
  }
  zeros = upper_half_then_real(zeros);
  poles = upper_half_then_real(poles);

  std::vector<Section> worst_first;
  for (std::size_t si = 0; si < section_count; ++si) {
    // The pole nearest the unit circle goes next.
    std::size_t worst = 0;
    for (std::size_t i = 1; i < poles.size(); ++i) {
      if (std::abs(1.0 - std::abs(poles[i])) < std::abs(1.0 - std::abs(poles[worst]))) worst = i;
    }
    const Complex p1 = take(poles, worst);
    if (is_real(p1) && count_real(poles) == 0) {
      // The last real pole: pair it with the nearest real zero.
      const Complex z1 = take(zeros, nearest_index(zeros, p1, Kind::kReal));
      worst_first.push_back(make_section({z1, Complex(0.0, 0.0)}, {p1, Complex(0.0, 0.0)}));
    } else if (poles.size() + 1 == zeros.size() && !is_real(p1) && count_real(poles) == 1 &&
               count_real(zeros) == 1) {
      // One real pole and one real zero left: this complex pole must take a complex zero.
      const Complex z1 = take(zeros, nearest_index(zeros, p1, Kind::kComplex));
      worst_first.push_back(make_section({z1}, {p1}));
    } else {
      std::vector<Complex> pole_pair{p1};
      if (is_real(p1)) {
        // Pair a real pole with the other real pole nearest the unit circle.
        std::size_t partner = poles.size();
        for (std::size_t i = 0; i < poles.size(); ++i) {
          if (!is_real(poles[i])) continue;
          if (partner == poles.size() ||
              std::abs(std::abs(poles[i]) - 1.0) < std::abs(std::abs(poles[partner]) - 1.0)) {
            partner = i;
          }
        }
        pole_pair.push_back(take(poles, partner));
      }
      std::vector<Complex> zero_pair;
      if (!zeros.empty()) {
        const Complex z1 = take(zeros, nearest_index(zeros, p1, Kind::kAny));
        zero_pair.push_back(z1);
        if (is_real(z1) && !zeros.empty()) {
          zero_pair.push_back(take(zeros, nearest_index(zeros, p1, Kind::kReal)));
        }
      }
      worst_first.push_back(make_section(zero_pair, pole_pair));
    }
  }
  std::reverse(worst_first.begin(), worst_first.end());
  return worst_first;
}

namespace {

Complex section_response(const Section& section, Complex w) {
  // b(w) / a(w) with w = z^-1, by Horner.
  const Complex numerator = section.b[0] + w * (section.b[1] + w * section.b[2]);
  const Complex denominator = section.a[0] + w * (section.a[1] + w * section.a[2]);
  return numerator / denominator;
}

double cumulative_magnitude(const std::vector<Section>& sections, std::size_t count, double omega) {
  const Complex w = std::polar(1.0, -omega);
  Complex product(1.0, 0.0);
  for (std::size_t k = 0; k < count; ++k) product *= section_response(sections[k], w);
  return std::abs(product);
}

// Frequencies where the peaks are looked for: a linear grid catches wide peaks, a logarithmic
// one the narrow peaks of filters whose cut-off is a tiny fraction of the sample rate.
const std::vector<double>& peak_search_grid() {
  static const std::vector<double> grid = [] {
    constexpr int kGridPoints = 2048;
    std::vector<double> points;
    points.reserve(2 * kGridPoints + 1);
    for (int i = 0; i <= kGridPoints; ++i) points.push_back(std::numbers::pi * i / kGridPoints);
    for (int i = 0; i < kGridPoints; ++i) {
      points.push_back(std::numbers::pi * std::pow(10.0, -7.0 + 7.0 * i / kGridPoints));
    }
    std::sort(points.begin(), points.end());
    return points;
  }();
  return grid;
}

// Golden-section refinement of a grid maximum at index `best` of the first `count` sections.
double refine_peak(const std::vector<Section>& sections, std::size_t count, std::size_t best,
                   double best_value) {
  const std::vector<double>& grid = peak_search_grid();
  double lo = grid[best == 0 ? 0 : best - 1];
  double hi = grid[std::min(best + 1, grid.size() - 1)];
  const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
  for (int iteration = 0; iteration < 60 && hi - lo > 1e-15; ++iteration) {
    const double left = hi - ratio * (hi - lo);
    const double right = lo + ratio * (hi - lo);
    if (cumulative_magnitude(sections, count, left) >
        cumulative_magnitude(sections, count, right)) {
      hi = right;
    } else {
      lo = left;
    }
  }
  return std::max(best_value, cumulative_magnitude(sections, count, (lo + hi) / 2.0));
}

// Running product of the section responses on the grid, one section at a time: the scaling
// costs O(sections x grid), not O(sections^2 x grid).
class CumulativeResponse {
 public:
  CumulativeResponse() {
    for (double omega : peak_search_grid()) {
      unit_delay_.push_back(std::polar(1.0, -omega));
      product_.emplace_back(1.0, 0.0);
    }
  }

  // Peak of the product so far followed by `next` (not yet multiplied in).
  double peak_with(const std::vector<Section>& sections, std::size_t count) const {
    const Section& next = sections[count - 1];
    std::size_t best = 0;
    double best_value = -1.0;
    for (std::size_t i = 0; i < product_.size(); ++i) {
      const double value = std::abs(product_[i] * section_response(next, unit_delay_[i]));
      if (value > best_value) {
        best_value = value;
        best = i;
      }
    }
    return refine_peak(sections, count, best, best_value);
  }

  void multiply(const Section& section) {
    for (std::size_t i = 0; i < product_.size(); ++i) {
      product_[i] *= section_response(section, unit_delay_[i]);
    }
  }

 private:
  std::vector<Complex> unit_delay_;
  std::vector<Complex> product_;
};

}  // namespace

double cumulative_peak_magnitude(const std::vector<Section>& sections, std::size_t count) {
  CumulativeResponse cumulative;
  for (std::size_t k = 0; k + 1 < count; ++k) cumulative.multiply(sections[k]);
  return cumulative.peak_with(sections, count);
}

ScaledCascade scale_cascade_linf(std::vector<Section> sections, double gain) {
  ScaledCascade cascade;
  CumulativeResponse cumulative;
  double placed = 1.0;  // product of the gains put into the sections so far
  for (std::size_t k = 0; k < sections.size(); ++k) {
    // The sections before k already carry their gains: this is the peak of the scaled cascade
    // so far followed by section k at unit gain.
    const double peak = cumulative.peak_with(sections, k + 1);
    double section_gain = 1.0 / peak;
    if (k + 1 == sections.size()) {
      // The last section carries the rest of the filter's gain unless that overflows.
      const double rest = gain / placed;
      const double tolerance = 1e-12;
      section_gain = (std::abs(rest) * peak <= 1.0 + tolerance) ? rest : 1.0 / peak;
    }
    for (double& coefficient : sections[k].b) coefficient *= section_gain;
    placed *= section_gain;
    cumulative.multiply(sections[k]);
  }
  cascade.leftover_gain = gain / placed;
  cascade.sections = std::move(sections);
  return cascade;
}

}  // namespace flange::coeffs
