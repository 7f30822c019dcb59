// SPDX-License-Identifier: MIT
#include "adc_grid.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <set>
#include <utility>
#include <vector>

#include "effect_classes.h"

namespace flange::diagnose {
namespace {

constexpr double kCsvRoundingV = 1.5e-6;  // the recording's 0.5 uV rounding, twice, plus slack
constexpr double kFinestLsbV = 20e-6;
constexpr double kMinShareOnGrid = 0.97;

// Within what a value counts as on a grid of step `lsb`.
double tolerance_for(double lsb) { return std::max(kCsvRoundingV, 2e-3 * lsb); }

// The smallest step between consecutive samples that recurs (at least max(3, n/1000) times):
// on a grid every step is a multiple of the LSB and one-LSB steps are the commonest non-zero
// ones, while a glitch's steps are rare. Steps are binned to 1 uV.
std::optional<double> recurring_smallest_step(const std::vector<double>& v) {
  // The binned steps sorted, then counted run by run: in ascending order as a map would hold
  // them, at a fraction of its cost on a 100 Hz log's quarter of a million steps.
  std::vector<long long> bins;
  bins.reserve(v.size());
  for (std::size_t i = 1; i < v.size(); ++i) {
    const double step = std::abs(v[i] - v[i - 1]);
    if (step > kCsvRoundingV) bins.push_back(std::llround(step * 1e6));
  }
  std::sort(bins.begin(), bins.end());
  std::vector<std::pair<long long, int>> counts;
  for (const long long bin : bins) {
    if (counts.empty() || counts.back().first != bin) counts.emplace_back(bin, 0);
    ++counts.back().second;
  }
  const int needed = std::max(3, static_cast<int>(v.size() / 1000));
  for (std::size_t k = 0; k < counts.size(); ++k) {
    // A step and its neighbouring 1 uV bins (rounding splits one step over two bins).
    const auto [micro_volts, count] = counts[k];
    int near = count;
    if (k + 1 < counts.size() && counts[k + 1].first == micro_volts + 1) near += counts[k + 1].second;
    if (near >= needed) return static_cast<double>(micro_volts) * 1e-6;
  }
  return std::nullopt;
}

// The LSB roughly, by least squares over the steps close to a multiple of `rough` (a step of
// m codes counts m times).
double lsb_from_steps(const std::vector<double>& v, double rough) {
  double sum_dm = 0.0, sum_mm = 0.0;
  for (std::size_t i = 1; i < v.size(); ++i) {
    const double step = std::abs(v[i] - v[i - 1]);
    const double m = std::round(step / rough);
    if (m < 1.0 || m > 50.0 || std::abs(step - m * rough) > 0.1 * rough) continue;
    sum_dm += step * m;
    sum_mm += m * m;
  }
  return sum_mm > 0.0 ? sum_dm / sum_mm : rough;
}

// A grid point: the circular mean of the values' phases within the LSB.
double grid_origin(const std::vector<double>& v, double lsb) {
  std::complex<double> sum = 0.0;
  for (const double x : v) sum += std::polar(1.0, 2.0 * std::numbers::pi * x / lsb);
  return lsb * std::arg(sum) / (2.0 * std::numbers::pi);
}

struct Lattice {
  double origin, lsb;
};

// Origin and LSB refitted by least squares of value on code over the values within `window`
// LSB of the lattice (odd values fall outside it).
Lattice refit(const std::vector<double>& v, Lattice lattice, double window) {
  double n = 0, sk = 0, sv = 0, skk = 0, skv = 0;
  for (const double x : v) {
    const double k = std::round((x - lattice.origin) / lattice.lsb);
    if (std::abs(x - lattice.origin - k * lattice.lsb) > window * lattice.lsb) continue;
    n += 1;
    sk += k;
    sv += x;
    skk += k * k;
    skv += k * x;
  }
  const double denominator = n * skk - sk * sk;
  if (n < 3 || denominator <= 0.0) return lattice;
  const double lsb = (n * skv - sk * sv) / denominator;
  return {(sv - lsb * sk) / n, lsb};
}

// Fills the codes used and spanned, the share on the grid and the extremes.
void count_codes(const std::vector<double>& v, double origin, AdcGrid& grid) {
  const double tolerance = tolerance_for(grid.lsb_v);
  std::set<long long> codes;
  long on_grid = 0;
  for (const double x : v) {
    const double code = std::round((x - origin) / grid.lsb_v);
    if (std::abs(x - origin - code * grid.lsb_v) > tolerance) continue;
    ++on_grid;
    codes.insert(static_cast<long long>(code));
  }
  grid.share_on_grid = static_cast<double>(on_grid) / static_cast<double>(v.size());
  if (codes.empty()) return;
  grid.codes_used = static_cast<long>(codes.size());
  grid.codes_spanned = static_cast<long>(*codes.rbegin() - *codes.begin() + 1);
  grid.lowest_v = origin + static_cast<double>(*codes.begin()) * grid.lsb_v;
  grid.highest_v = origin + static_cast<double>(*codes.rbegin()) * grid.lsb_v;
}

// The range the twin's converter is given: a usual one if this grid is one of its 2^k grids
// and it holds the data, else 2^bits codes from the lowest used.
void choose_range(AdcGrid& grid) {
  grid.bits = 4;
  while (std::ldexp(1.0, grid.bits) < static_cast<double>(grid.codes_spanned) && grid.bits < 24) {
    ++grid.bits;
  }
  const std::pair<double, double> usual[] = {{-10, 10}, {0, 10}, {-5, 5}, {0, 5}};
  for (const auto& [lo, hi] : usual) {
    const double k = std::log2((hi - lo) / grid.lsb_v);
    const double on = (grid.lowest_v - lo) / grid.lsb_v;
    if (std::abs(k - std::round(k)) < 1e-4 && std::abs(on - std::round(on)) < 0.02 &&
        grid.lowest_v >= lo - 1e-9 && grid.highest_v <= hi + 1e-9 && k >= 4 && k <= 24) {
      grid.bits = static_cast<int>(std::round(k));
      grid.v_min = lo;
      grid.v_max = hi;
      grid.usual_range = true;
      return;
    }
  }
  grid.v_min = grid.lowest_v;
  grid.v_max = grid.lowest_v + std::ldexp(grid.lsb_v, grid.bits);
}

// The grid's LSB against the nearest span / 2^k (4 to 24 bits) of a usual converter range: a
// ratio within kMostCalibrationGain of 1, but not 1 to the grid's own precision, is the DAQ
// software's gain calibration.
double calibration_gain_of(double lsb_v) {
  constexpr double kSpansV[] = {5.0, 10.0, 20.0, 4.096, 10.24, 20.48};
  double nearest = 1.0, off = std::numeric_limits<double>::infinity();
  for (const double span : kSpansV) {
    const double bits = std::round(std::log2(span / lsb_v));
    if (bits < 4 || bits > 24) continue;
    const double ratio = lsb_v / std::ldexp(span, -static_cast<int>(bits));
    if (std::abs(ratio - 1.0) < off) {
      off = std::abs(ratio - 1.0);
      nearest = ratio;
    }
  }
  return off <= kMostCalibrationGain && off > 1e-4 ? nearest : 1.0;
}

}  // namespace

double AdcGrid::quantise(double volts) const {
  return lowest_v + lsb_v * std::round((volts - lowest_v) / lsb_v);
}

sim::EffectSettings AdcGrid::as_effect() const {
  return sim::make_effect_settings(
      converter_class(), {{"bits", static_cast<double>(bits)}, {"v_min", v_min}, {"v_max", v_max}},
      "diagnose grid");
}

std::optional<AdcGrid> estimate_adc_grid(const std::vector<double>& voltage_v) {
  if (voltage_v.size() < 16) return std::nullopt;
  const std::optional<double> rough = recurring_smallest_step(voltage_v);
  if (!rough || *rough < kFinestLsbV) return std::nullopt;
  const double lsb = lsb_from_steps(voltage_v, *rough);
  Lattice lattice{grid_origin(voltage_v, lsb), lsb};
  for (const double window : {0.1, 0.02, 0.005}) lattice = refit(voltage_v, lattice, window);
  AdcGrid grid;
  grid.lsb_v = lattice.lsb;
  count_codes(voltage_v, lattice.origin, grid);
  if (grid.share_on_grid < kMinShareOnGrid || grid.codes_used < 3) return std::nullopt;
  choose_range(grid);
  if (!grid.usual_range) grid.calibration_gain = calibration_gain_of(grid.lsb_v);
  return grid;
}

}  // namespace flange::diagnose
