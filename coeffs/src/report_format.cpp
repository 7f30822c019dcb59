// SPDX-License-Identifier: MIT
#include "report_format.h"

#include <fmt/format.h>

#include <cmath>

namespace flange::coeffs {

std::string gnuplot_data_block(const std::string& name,
                               const std::vector<std::vector<double>>& columns) {
  std::string text = "$" + name + " << EOD\n";
  for (std::size_t row = 0; row < columns.front().size(); ++row) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const double v = columns[c][row];
      text += std::isfinite(v) ? fmt::format("{:.7g}", v) : "NaN";
      text += c + 1 == columns.size() ? "\n" : " ";
    }
  }
  return text + "EOD\n";
}

std::string gnuplot_svg_terminal(const std::filesystem::path& path, int width, int height,
                                 bool enhanced_text, bool grid) {
  return fmt::format(
      "set terminal svg size {},{} dynamic {}font 'sans,12' background '#ffffff'\nset output "
      "'{}'\n{}",
      width, height, enhanced_text ? "" : "noenhanced ", path.string(), grid ? "set grid\n" : "");
}

std::string html_escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else
      out += c;
  }
  return out;
}

}  // namespace flange::coeffs
