// SPDX-License-Identifier: MIT
#include "mains_lines.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "grid_search.h"

namespace flange::diagnose::free_shapes {
namespace {

// Up to two lines near each alias: the harmonics of a grid off its nominal frequency land a
// little apart.
constexpr int kMainsLinesPerAlias = 2;
// A line is kept when its window-by-window fit lowers the mean square by more than four times
// what fitting its values to white noise takes on average. Over a session's tens of windows that
// chance reduction is a sum of as many small chi-square terms, whose spread is a fraction of its
// mean: four times the mean is far in its tail.
constexpr double kMainsLineFactor = 4.0;
// The frequency within kMainsSearchHz of `nominal_hz` whose window-by-window fit leaves the
// least of `gap`, on a lattice of kMainsStepHz.
double refine_line(const std::vector<double>& t, const std::vector<double>& gap,
                   double nominal_hz) {
  SearchPoint best{{nominal_hz}};
  const Objective left_by = [&](const std::vector<double>& at) {
    const double f = at[0];
    if (f <= 0.0) return std::numeric_limits<double>::infinity();  // never taken
    int values = 0;
    const std::vector<double> tone = windowed_tones(t, gap, {f}, values);
    double left = 0.0;
    for (std::size_t i = 0; i < gap.size(); ++i) left += (gap[i] - tone[i]) * (gap[i] - tone[i]);
    return left;
  };
  search_points_at_once(lattice({stepped_axis(nominal_hz - kMainsSearchHz,
                                              nominal_hz + kMainsSearchHz + 1e-9, kMainsStepHz)}),
                        left_by, best);
  return best.at[0];
}

}  // namespace

double alias_hz(double f_hz, double fs_hz) {
  const double folded = std::fmod(f_hz, fs_hz);
  return std::min(folded, fs_hz - folded);
}

MainsAliases mains_aliases(double fs_hz) {
  MainsAliases aliases;
  for (double mains_hz : {50.0, 60.0}) {
    for (int h = 1; h <= kMainsHarmonics; ++h) {
      const double f = alias_hz(h * mains_hz, fs_hz);
      if (f < kMainsSearchHz + 2.0 / kMainsWindowS || f > 0.5 * fs_hz - kMainsSearchHz) continue;
      aliases.of_harmonics.push_back({f, mains_hz});
      if (std::none_of(aliases.distinct_hz.begin(), aliases.distinct_hz.end(),
                       [&](double g) { return std::abs(g - f) < kMainsSearchHz; })) {
        aliases.distinct_hz.push_back(f);
      }
    }
  }
  return aliases;
}

std::vector<std::pair<std::size_t, std::size_t>> mains_windows(const std::vector<double>& t,
                                                               double window_s) {
  const std::size_t n = t.size();
  std::vector<std::pair<std::size_t, std::size_t>> windows;
  for (std::size_t begin = 0; begin < n;) {
    std::size_t end = begin;
    while (end < n && t[end] < t[begin] + window_s) ++end;
    if (n - end < (end - begin) / 2) end = n;
    windows.emplace_back(begin, end);
    begin = end;
  }
  return windows;
}

std::vector<double> windowed_tones(const std::vector<double>& t, const std::vector<double>& gap,
                                   const std::vector<double>& tones_hz, int& values,
                                   double window_s) {
  const std::size_t n = t.size();
  std::vector<double> out(n, 0.0);
  values = 0;
  const auto cols = static_cast<Eigen::Index>(1 + 2 * tones_hz.size());
  for (const auto& [begin, end] : mains_windows(t, window_s)) {
    const auto rows = static_cast<Eigen::Index>(end - begin);
    if (rows > 2 * cols) {
      Eigen::MatrixXd a(rows, cols);
      Eigen::VectorXd y(rows);
      for (Eigen::Index r = 0; r < rows; ++r) {
        const std::size_t i = begin + static_cast<std::size_t>(r);
        a(r, 0) = 1.0;
        for (std::size_t k = 0; k < tones_hz.size(); ++k) {
          const double phase = 2.0 * std::numbers::pi * tones_hz[k] * (t[i] - t[begin]);
          a(r, static_cast<Eigen::Index>(1 + 2 * k)) = std::cos(phase);
          a(r, static_cast<Eigen::Index>(2 + 2 * k)) = std::sin(phase);
        }
        y(r) = gap[i];
      }
      Eigen::VectorXd beta = a.colPivHouseholderQr().solve(y);
      beta(0) = 0.0;
      const Eigen::VectorXd tone = a * beta;
      for (Eigen::Index r = 0; r < rows; ++r) out[begin + static_cast<std::size_t>(r)] = tone(r);
      values += static_cast<int>(2 * tones_hz.size());
    }
  }
  return out;
}

double mean_square(const std::vector<double>& x) {
  double sum = 0.0;
  for (double v : x) sum += v * v;
  return x.empty() ? 0.0 : sum / static_cast<double>(x.size());
}

// The figure a line must pass is a share of what is left, so a weak line looked at before a
// strong one's removal can fall short: the aliases are gone through again while a pass keeps a
// line (a grid's weak second harmonic beside a strong fundamental).
std::vector<double> find_lines(const std::vector<double>& t, const std::vector<double>& gap,
                               const std::vector<double>& nominals_hz) {
  std::vector<double> found;
  std::vector<double> left = gap;
  std::vector<int> lines_near(nominals_hz.size(), 0);
  std::vector<bool> done(nominals_hz.size(), false);
  // How many lines were kept when an alias last fell short: with no line kept since, what is
  // left is the same and so would the answer be.
  std::vector<std::size_t> short_at(nominals_hz.size(), std::numeric_limits<std::size_t>::max());
  for (bool kept_one = true; kept_one;) {
    kept_one = false;
    for (std::size_t a = 0; a < nominals_hz.size(); ++a) {
      while (!done[a] && lines_near[a] < kMainsLinesPerAlias && short_at[a] != found.size()) {
        const double f = refine_line(t, left, nominals_hz[a]);
        if (std::any_of(found.begin(), found.end(),
                        [&](double g) { return std::abs(g - f) < 0.5 * kMainsStepHz; })) {
          done[a] = true;
          break;
        }
        std::vector<double> trial = found;
        trial.push_back(f);
        int values = 0;
        const std::vector<double> tones = windowed_tones(t, gap, trial, values);
        std::vector<double> after(gap.size());
        for (std::size_t i = 0; i < gap.size(); ++i) after[i] = gap[i] - tones[i];
        const double per_line = static_cast<double>(values) / static_cast<double>(trial.size()) + 1;
        const double chance = mean_square(after) * per_line / static_cast<double>(gap.size());
        if (mean_square(left) - mean_square(after) <= kMainsLineFactor * chance) {
          short_at[a] = found.size();
          break;
        }
        found = std::move(trial);
        left = std::move(after);
        ++lines_near[a];
        kept_one = true;
      }
    }
  }
  return found;
}

}  // namespace flange::diagnose::free_shapes
