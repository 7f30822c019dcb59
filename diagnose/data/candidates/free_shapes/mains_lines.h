// SPDX-License-Identifier: MIT
// Lines of the mains in a gap: tones at the aliases of 50 or 60 Hz and their harmonics, whose
// phase is wherever the mains was when each session started and whose frequency wanders with the
// grid, fitted window by window (amplitude and phase free in each window).
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

namespace flange::diagnose::free_shapes {

// Windows of 20 s: 120 samples or more, so the two values of a line in each cost under 2 % of the
// noise variance; a line found within 0.0125 Hz of its frequency turns by under a quarter cycle
// across one. Each part's own lines are found within 0.15 Hz of the nominal aliases (a grid
// 0.02 Hz off, seventh harmonic), on a 0.01 Hz lattice.
inline constexpr double kMainsWindowS = 20.0;
inline constexpr double kMainsSearchHz = 0.15;
inline constexpr double kMainsStepHz = 0.01;
inline constexpr int kMainsHarmonics = 7;
// How near 0 Hz a harmonic's alias must land to be a constant of each session (half the line
// search's step).
inline constexpr double kDcAliasHz = 0.005;

// Where a tone at `f_hz` lands when sampled at `fs_hz`: in [0, fs / 2].
double alias_hz(double f_hz, double fs_hz);

// One alias of one harmonic of a mains frequency.
struct MainsAlias {
  double hz = 0.0;
  double mains_hz = 0.0;  // 50 or 60
};
struct MainsAliases {
  // Every distinct alias (no two within kMainsSearchHz), away from DC and from fs/2, where a
  // window cannot tell a line from a constant or from its own mirror.
  std::vector<double> distinct_hz;
  // Every harmonic's alias there, with its mains.
  std::vector<MainsAlias> of_harmonics;
};
// The aliases of the harmonics (up to kMainsHarmonics) of 50 and 60 Hz at `fs_hz`.
MainsAliases mains_aliases(double fs_hz);

// The mains windows of a part, [begin, end) row ranges of `window_s` each; a short last window
// joins the one before it.
std::vector<std::pair<std::size_t, std::size_t>> mains_windows(const std::vector<double>& t,
                                                               double window_s = kMainsWindowS);

// Least squares of `gap` on the tones at `tones_hz` in windows of `window_s` seconds (a constant
// per window as a nuisance, left out of what is returned); `values` counts the values fitted.
std::vector<double> windowed_tones(const std::vector<double>& t, const std::vector<double>& gap,
                                   const std::vector<double>& tones_hz, int& values,
                                   double window_s = kMainsWindowS);

double mean_square(const std::vector<double>& x);

// The lines of `gap` near each of `nominals_hz`: up to kMainsLinesPerAlias each, each found on
// what the lines before it leave and kept when it lowers the mean square by more than
// kMainsLineFactor times what its values would take from white noise.
std::vector<double> find_lines(const std::vector<double>& t, const std::vector<double>& gap,
                               const std::vector<double>& nominals_hz);

}  // namespace flange::diagnose::free_shapes
