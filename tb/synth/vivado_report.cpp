// SPDX-License-Identifier: MIT
#include "vivado_report.h"

#include <fmt/format.h>

#include <fstream>
#include <map>
#include <regex>
#include <sstream>

namespace flange::tb {
namespace fs = std::filesystem;

namespace {

struct Lines {
  std::vector<std::string> text;
  std::string file;
  [[noreturn]] void fail(std::size_t index, const std::string& what) const {
    throw VivadoReportError(fmt::format("{}:{}: {}", file, index + 1, what));
  }
};

Lines split_lines(const std::string& text, const std::string& file) {
  Lines lines{{}, file};
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.text.push_back(line);
  }
  return lines;
}

std::string trim(const std::string& s) {
  const std::size_t b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

// The index of the first line at or after `from` whose trimmed text starts with `prefix`.
std::optional<std::size_t> find_line(const Lines& lines, const std::string& prefix,
                                     std::size_t from = 0) {
  for (std::size_t i = from; i < lines.text.size(); ++i)
    if (trim(lines.text[i]).rfind(prefix, 0) == 0) return i;
  return std::nullopt;
}

// Column names of a header such as "    WNS(ns)      TNS(ns)  TNS Failing Endpoints": split at
// runs of two or more spaces.
std::vector<std::string> header_columns(const std::string& line) {
  std::vector<std::string> columns;
  static const std::regex gap(R"(\s{2,})");
  const std::string t = trim(line);
  for (std::sregex_token_iterator it(t.begin(), t.end(), gap, -1), end; it != end; ++it)
    if (!it->str().empty()) columns.push_back(it->str());
  return columns;
}

std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> w;
  for (std::string s; in >> s;) w.push_back(s);
  return w;
}

double number(const Lines& lines, std::size_t index, const std::string& field,
              const std::string& value) {
  static const std::regex real(R"(-?\d+(\.\d+)?)");
  if (!std::regex_match(value, real)) {
    lines.fail(index, fmt::format("field {}: \"{}\" is not a number", field, value));
  }
  return std::stod(value);
}

// A table of `report_timing_summary`: the header after `title`, its dashes, and the value rows
// up to the first blank line, as column -> value per row.
std::vector<std::pair<std::size_t, std::map<std::string, std::string>>> summary_table(
    const Lines& lines, const std::string& title, const std::string& first_column) {
  const auto at = find_line(lines, "| " + title);
  if (!at) lines.fail(lines.text.size() - 1, "no \"" + title + "\" table");
  const auto header = find_line(lines, first_column, *at);
  if (!header || *header > *at + 8) lines.fail(*at, "the \"" + title + "\" table has no header");
  const std::vector<std::string> columns = header_columns(lines.text[*header]);
  std::vector<std::pair<std::size_t, std::map<std::string, std::string>>> rows;
  std::size_t i = *header + 2;  // past the dashes
  while (i < lines.text.size() && trim(lines.text[i]).empty()) ++i;
  for (; i < lines.text.size() && !trim(lines.text[i]).empty(); ++i) {
    std::vector<std::string> values = words(lines.text[i]);
    if (first_column == "Clock" && title == "Clock Summary") {
      // "name  {0.000 5.000}  10.000  100.000": the waveform holds a space.
      static const std::regex row(R"(^\s*(\S+)\s+\{([^}]*)\}\s+(\S+)\s+(\S+)\s*$)");
      std::smatch m;
      if (!std::regex_match(lines.text[i], m, row))
        lines.fail(i,
                   "a Clock Summary row without "
                   "name, waveform, period, frequency");
      values = {m[1], "{" + m[2].str() + "}", m[3], m[4]};
    }
    if (values.size() != columns.size()) {
      lines.fail(i, fmt::format("the \"{}\" row has {} values for {} columns", title, values.size(),
                                columns.size()));
    }
    std::map<std::string, std::string> row;
    for (std::size_t c = 0; c < columns.size(); ++c) row[columns[c]] = values[c];
    rows.emplace_back(i, row);
  }
  if (rows.empty()) lines.fail(*header, "the \"" + title + "\" table has no rows");
  return rows;
}

const std::string& field(const Lines& lines, std::size_t index,
                         const std::map<std::string, std::string>& row, const std::string& name) {
  auto it = row.find(name);
  if (it == row.end()) lines.fail(index, "no column " + name);
  return it->second;
}

std::optional<double> optional_number(const Lines& lines, std::size_t index,
                                      const std::map<std::string, std::string>& row,
                                      const std::string& name) {
  auto it = row.find(name);
  if (it == row.end() || it->second == "NA") return std::nullopt;
  return number(lines, index, name, it->second);
}

std::optional<VivadoPath> worst_setup_path(const Lines& lines) {
  const auto max_paths = find_line(lines, "Max Delay Paths");
  if (!max_paths) return std::nullopt;
  const auto slack = find_line(lines, "Slack", *max_paths);
  if (!slack) return std::nullopt;
  VivadoPath path;
  static const std::regex slack_line(R"(Slack\s*\((MET|VIOLATED)\)\s*:\s*(-?[\d.]+)ns)");
  static const std::regex delay_line(
      R"(Data Path Delay:\s*([\d.]+)ns\s*\(logic\s*([\d.]+)ns.*route\s*([\d.]+)ns)");
  std::smatch m;
  if (!std::regex_search(lines.text[*slack], m, slack_line))
    lines.fail(*slack,
               "field Slack: no "
               "figure in ns");
  path.slack_ns = std::stod(m[2]);
  auto value_of = [&](const std::string& key) -> std::pair<std::size_t, std::string> {
    const auto at = find_line(lines, key, *slack);
    if (!at || *at > *slack + 12) lines.fail(*slack, "the worst path has no " + key);
    const std::string t = trim(lines.text[*at]);
    return {*at, trim(t.substr(key.size()))};
  };
  path.source = words(value_of("Source:").second).at(0);
  path.destination = words(value_of("Destination:").second).at(0);
  const auto [delay_at, delay] = value_of("Data Path Delay:");
  if (!std::regex_search(lines.text[delay_at], m, delay_line)) {
    lines.fail(delay_at, "field Data Path Delay: not \"N ns (logic N ns ... route N ns ...)\"");
  }
  path.data_path_ns = std::stod(m[1]);
  path.logic_ns = std::stod(m[2]);
  path.route_ns = std::stod(m[3]);
  const auto [levels_at, levels] = value_of("Logic Levels:");
  path.logic_levels =
      static_cast<int>(number(lines, levels_at, "Logic Levels", words(levels).at(0)));
  return path;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  if (!in)
    throw VivadoReportMissing(path.string() + ": cannot be read (run rtl/board/vivado_build.tcl)");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

VivadoTiming parse_timing_summary(const std::string& text, const std::string& file) {
  const Lines lines = split_lines(text, file);
  if (lines.text.empty()) throw VivadoReportError(file + ":1: the file is empty");
  VivadoTiming t;
  const auto design = summary_table(lines, "Design Timing Summary", "WNS(ns)");
  const auto& [at, row] = design.front();
  const std::string& wns = field(lines, at, row, "WNS(ns)");
  if (wns == "NA") lines.fail(at, "field WNS(ns): NA (no constrained path: is the clock defined?)");
  t.wns_ns = number(lines, at, "WNS(ns)", wns);
  t.tns_ns = number(lines, at, "TNS(ns)", field(lines, at, row, "TNS(ns)"));
  t.failing_endpoints = static_cast<int>(
      number(lines, at, "TNS Failing Endpoints", field(lines, at, row, "TNS Failing Endpoints")));
  t.total_endpoints = static_cast<int>(
      number(lines, at, "TNS Total Endpoints", field(lines, at, row, "TNS Total Endpoints")));
  t.whs_ns = optional_number(lines, at, row, "WHS(ns)");
  for (const auto& [i, clock] : summary_table(lines, "Clock Summary", "Clock")) {
    VivadoClock c;
    c.name = field(lines, i, clock, "Clock");
    c.period_ns = number(lines, i, "Period(ns)", field(lines, i, clock, "Period(ns)"));
    t.clocks.push_back(c);
  }
  if (find_line(lines, "| Intra Clock Table")) {
    for (const auto& [i, intra] : summary_table(lines, "Intra Clock Table", "Clock")) {
      for (VivadoClock& c : t.clocks) {
        if (c.name != field(lines, i, intra, "Clock")) continue;
        c.wns_ns = optional_number(lines, i, intra, "WNS(ns)");
        c.whs_ns = optional_number(lines, i, intra, "WHS(ns)");
      }
    }
  }
  t.worst_path = worst_setup_path(lines);
  return t;
}

VivadoUtilisation parse_utilization(const std::string& text, const std::string& file) {
  const Lines lines = split_lines(text, file);
  if (lines.text.empty()) throw VivadoReportError(file + ":1: the file is empty");
  VivadoUtilisation u;
  if (const auto device = find_line(lines, "| Device")) {
    const std::string& l = lines.text[*device];
    u.device = trim(l.substr(l.find(':') + 1));
  }
  // Every "| Site Type | Used | ... |" table: site type -> (line, Used); the first row of a type
  // counts.
  std::map<std::string, std::pair<std::size_t, std::string>> used;
  for (std::size_t i = 0; i < lines.text.size(); ++i) {
    if (lines.text[i].rfind("|", 0) != 0) continue;
    std::vector<std::string> header;
    std::stringstream cells(lines.text[i]);
    for (std::string c; std::getline(cells, c, '|');) header.push_back(trim(c));
    if (header.size() < 2 || header[1] != "Site Type") continue;
    std::size_t used_col = 0;
    while (used_col < header.size() && header[used_col] != "Used") ++used_col;
    if (used_col == header.size()) lines.fail(i, "a Site Type table without a Used column");
    for (std::size_t r = i + 2; r < lines.text.size() && lines.text[r].rfind("|", 0) == 0; ++r) {
      std::vector<std::string> row;
      std::stringstream rc(lines.text[r]);
      for (std::string c; std::getline(rc, c, '|');) row.push_back(trim(c));
      std::string site = row.size() > 1 ? row[1] : "";
      while (!site.empty() && site.back() == '*') site.pop_back();
      if (row.size() > used_col && !used.count(site)) used[site] = {r, row[used_col]};
    }
  }
  auto get = [&](const std::string& site) -> std::optional<double> {
    auto it = used.find(site);
    if (it == used.end()) return std::nullopt;
    return number(lines, it->second.first, site + " Used", it->second.second);
  };
  const auto luts = get("Slice LUTs"), registers = get("Slice Registers");
  if (!luts) lines.fail(0, "field Slice LUTs: no \"Slice Logic\" table row");
  if (!registers) lines.fail(0, "field Slice Registers: no \"Slice Logic\" table row");
  u.slice_luts = static_cast<int>(*luts);
  u.slice_registers = static_cast<int>(*registers);
  auto as_int = [](std::optional<double> v) -> std::optional<int> {
    return v ? std::optional<int>(static_cast<int>(*v)) : std::nullopt;
  };
  u.lut_as_memory = as_int(get("LUT as Memory"));
  u.f7_muxes = as_int(get("F7 Muxes"));
  u.f8_muxes = as_int(get("F8 Muxes"));
  u.dsps = as_int(get("DSPs"));
  u.bonded_iob = as_int(get("Bonded IOB"));
  u.block_ram_tiles = get("Block RAM Tile");
  return u;
}

VivadoReport read_vivado_report(const fs::path& dir) {
  VivadoReport report;
  report.dir = dir;
  const fs::path timing = dir / "timing_summary.rpt", utilisation = dir / "utilization.rpt";
  report.timing = parse_timing_summary(read_text(timing), timing.string());
  report.utilisation = parse_utilization(read_text(utilisation), utilisation.string());
  return report;
}

}  // namespace flange::tb
