// SPDX-License-Identifier: MIT
// Text formats shared by every report the project writes (design, run, diagnosis): gnuplot data
// blocks and SVG terminal lines, and HTML escaping. The plots themselves run through
// gnuplot_runner.h.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace flange::coeffs {

// A gnuplot inline data block `$name << EOD ... EOD`, one row per sample of the columns (all of
// the same length), 7 significant digits, NaN for a non-finite value.
std::string gnuplot_data_block(const std::string& name,
                               const std::vector<std::vector<double>>& columns);

// The lines that point gnuplot at an SVG file of width x height pixels. enhanced_text = false
// prints labels as they are (no ^ or _ markup); grid adds `set grid`.
std::string gnuplot_svg_terminal(const std::filesystem::path& path, int width, int height,
                                 bool enhanced_text = true, bool grid = true);

// `text` with <, > and & escaped for HTML.
std::string html_escape(const std::string& text);

}  // namespace flange::coeffs
