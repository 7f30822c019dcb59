// SPDX-License-Identifier: MIT
// A sample rate at which mains pickup and mount motion that fold onto one line of a recording
// fold to different frequencies: the arithmetic of aliasing alone.
#pragma once

#include <optional>
#include <vector>

namespace flange::diagnose {

// Where a tone at `f_hz` shows when sampled at `fs_hz`: in [0, fs / 2].
double folded_hz(double f_hz, double fs_hz);

// Motion's highest frequency asked about: the bogie's and mount's modes lie below it, and 100 Hz
// is the fastest rate the project's loggers record at.
inline constexpr double kHighestMotionHz = 100.0;
// How far apart two lines must fold to be two lines: twice the mains line search's reach
// (free_shapes/mains_lines.h, kMainsSearchHz), so that neither is found near the other's alias.
inline constexpr double kSeparatedLinesHz = 0.3;

// The frequencies mount motion may have that fold onto `line_hz` at `fs_hz`: k fs +- line_hz up to
// kHighestMotionHz, less those within kSeparatedLinesHz of a harmonic in `mains_harmonics_hz`
// (motion at the mains' own frequency folds with it at every rate).
std::vector<double> motion_folding_onto(double line_hz, double fs_hz,
                                        const std::vector<double>& mains_harmonics_hz);

// The rate (Hz, 6 to 100 in steps of 0.5) nearest `fs_hz` at which every harmonic in
// `mains_harmonics_hz` (those that fold onto the line at `fs_hz`) folds to a line of its own
// (kSeparatedLinesHz from 0 Hz and from the new Nyquist frequency) at least kSeparatedLinesHz from
// where every frequency of motion_folding_onto() folds; none when no such rate exists.
std::optional<double> separating_rate_hz(double line_hz, double fs_hz,
                                         const std::vector<double>& mains_harmonics_hz);

}  // namespace flange::diagnose
