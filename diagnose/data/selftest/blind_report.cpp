// SPDX-License-Identifier: MIT
#include "blind_report.h"

#include <fmt/format.h>

#include "verdict_reasons.h"
#include "version.h"

namespace flange::diagnose {
namespace {

// A column of a table: in the terminal padded to `width` (0: the last column, not padded).
struct Column {
  std::string title;
  int width = 0;
  bool right = false;  // right-aligned (in selftest.md too)
  std::function<std::string(const BlindRow&)> cell;
};

std::string join(const std::vector<std::string>& names) {
  if (names.empty()) return "-";
  std::string text;
  for (const std::string& n : names) text += (text.empty() ? "" : ", ") + (n.empty() ? "?" : n);
  return text;
}

std::string yes_no(const BlindRow& row, bool value) {
  if (!in_library(row.truth.kind)) return "";
  return value ? "yes" : "no";
}

std::string nearest_cell(const BlindRow& row) {
  const BlindScore& score = row.outcome->score;
  if (row.outcome->diagnosis.status != Status::kUnexplained || score.nearest.empty()) return "";
  return fmt::format(
      "{} {:.0f}%{}", score.nearest, score.nearest_shrink_pct,
      in_library(row.truth.kind) ? (score.nearest_correct ? " (yes)" : " (no)") : "");
}

std::string percent(int part, int whole) {
  return whole == 0 ? "n/a" : fmt::format("{:.0f} %", 100.0 * part / whole);
}

const BlindScore& score_of(const BlindRow& row) { return row.outcome->score; }

// The cells the two tables share.
Column index_column(const BlindStyle& style) {
  return {style.noun, 4, true, [](const BlindRow& r) { return std::to_string(r.index); }};
}
Column kind_column() { return {"kind", 7, false, &BlindRow::kind_name}; }
Column truth_column(const std::string& title) { return {title, 0, false, &BlindRow::truth_text}; }
Column verdict_column() {
  return {"verdict", 11, false,
          [](const BlindRow& r) { return std::string(status_text(r.outcome->diagnosis.status)); }};
}
Column named_column(const BlindStyle& style) {
  return {style.named_title, style.named_width, false,
          [](const BlindRow& r) { return join(score_of(r).claimed); }};
}
Column nearest_column() { return {"nearest (unexplained)", 30, false, nearest_cell}; }
// "yes" or "no" for an in-library case, else empty.
Column yes_no_column(const std::string& title, bool BlindScore::*member) {
  return {title, 3, false, [member](const BlindRow& r) { return yes_no(r, score_of(r).*member); }};
}
Column noise_column(const std::string& title) {
  return {title, 6, true, [](const BlindRow& r) { return fmt::format("{:.3f}", r.noise_v); }};
}
// A shrink, "12.3%" in the terminal (`unit` "%"), "12.3" in selftest.md.
Column shrink_column(const std::string& title, double BlindScore::*member,
                     const std::string& unit) {
  return {title, 7, true, [member, unit](const BlindRow& r) {
            return fmt::format("{:.1f}{}", score_of(r).*member, unit);
          }};
}

std::vector<Column> terminal_columns(const BlindStyle& style) {
  std::vector<Column> columns = {index_column(style),
                                 kind_column(),
                                 verdict_column(),
                                 yes_no_column("top", &BlindScore::top_correct),
                                 yes_no_column("all", &BlindScore::all_found),
                                 shrink_column("shrink", &BlindScore::shrink_pct, "%"),
                                 shrink_column("excess", &BlindScore::excess_shrink_pct, "%")};
  if (style.shows_noise) columns.push_back(noise_column("noise"));
  columns.push_back(named_column(style));
  if (style.shows_nearest) columns.push_back(nearest_column());
  columns.push_back(truth_column("truth"));
  return columns;
}

std::vector<Column> markdown_columns(const BlindStyle& style) {
  std::vector<Column> columns = {index_column(style), kind_column(),
                                 truth_column(style.truth_title)};
  if (style.shows_noise) columns.push_back(noise_column("noise V"));
  columns.push_back(verdict_column());
  columns.push_back(named_column(style));
  if (style.shows_nearest) columns.push_back(nearest_column());
  columns.push_back(yes_no_column("top", &BlindScore::top_correct));
  columns.push_back(yes_no_column("all", &BlindScore::all_found));
  columns.push_back(shrink_column("shrink %", &BlindScore::shrink_pct, ""));
  columns.push_back(shrink_column("above-noise shrink %", &BlindScore::excess_shrink_pct, ""));
  return columns;
}

std::string terminal_line(const std::vector<Column>& columns,
                          const std::function<std::string(const Column&)>& text) {
  std::string line;
  for (std::size_t k = 0; k < columns.size(); ++k) {
    const Column& c = columns[k];
    if (k > 0) line += "  ";
    if (c.width == 0) {
      line += text(c);
    } else {
      line += c.right ? fmt::format("{:>{}}", text(c), c.width)
                      : fmt::format("{:<{}}", text(c), c.width);
    }
  }
  return line + "\n";
}

std::string terminal_table(const BlindStyle& style, const std::vector<BlindRow>& rows) {
  const std::vector<Column> columns = terminal_columns(style);
  std::string text = terminal_line(columns, [](const Column& c) { return c.title; });
  for (const BlindRow& row : rows) {
    text += terminal_line(columns, [&](const Column& c) { return c.cell(row); });
  }
  return text;
}

std::string markdown_table(const BlindStyle& style, const std::vector<BlindRow>& rows) {
  const std::vector<Column> columns = markdown_columns(style);
  std::string titles = "|", rule = "|";
  for (const Column& c : columns) {
    titles += " " + c.title + " |";
    rule += c.right ? "---:|" : "---|";
  }
  std::string text = titles + "\n" + rule + "\n";
  for (const BlindRow& row : rows) {
    text += "|";
    for (const Column& c : columns) text += " " + c.cell(row) + " |";
    text += "\n";
  }
  return text;
}

std::string class_table(const BlindSummary& summary) {
  std::string text =
      "| class | pairs | right top class | class named | above-noise shrink (bias-type pairs) |\n"
      "|---|---:|---:|---:|---:|\n";
  for (const BlindClassRow& row : summary.classes) {
    text +=
        fmt::format("| {} | {} | {} | {} | {} |\n", row.name, row.pairs, row.top_correct, row.named,
                    row.bias_pairs > 0
                        ? fmt::format("{:.1f} % ({})", row.mean_excess_shrink_pct, row.bias_pairs)
                        : std::string("-"));
  }
  return text;
}

nlohmann::json case_json(const BlindStyle& style, const BlindRow& row) {
  const Diagnosis& d = row.outcome->diagnosis;
  const BlindScore& score = row.outcome->score;
  nlohmann::json j = row.truth_json;
  j["verdict"] = status_text(d.status);
  j[style.claimed_key] = score.claimed;
  j["verdict_correct"] = score.verdict_correct;
  if (in_library(row.truth.kind)) {
    j["top_correct"] = score.top_correct;
    j["all_found"] = score.all_found;
    j["top_among_indistinguishable"] = score.top_among_indistinguishable;
    j["all_among_indistinguishable"] = score.all_among_indistinguishable;
    j["spurious"] = score.spurious;
    j["bias_type"] = score.bias_type;
    if (style.shows_nearest) j["nearest_correct"] = score.nearest_correct;
  }
  if (style.shows_nearest) {
    j["nearest_class"] = score.nearest;
    j["nearest_shrink_pct"] = score.nearest_shrink_pct;
  }
  j["heldout_rms_before"] = d.heldout_rms_before;
  j["heldout_rms_after"] = d.heldout_rms_after;
  j["noise_std_v_estimated"] = d.noise_std_v;
  j["shrink_pct"] = score.shrink_pct;
  j["excess_shrink_pct"] = score.excess_shrink_pct;
  j["claims"] = claims_json(d.effects, score.claimed, score.claim_right);
  j["seconds"] = row.outcome->seconds;
  if (style.add_case_json) style.add_case_json(row, j);
  return j;
}

nlohmann::json summary_json(const BlindStyle& style, const BlindSummary& s) {
  nlohmann::json j = {{"in_library", s.in_library},
                      {"top_correct", s.top_correct},
                      {"all_found", s.all_found},
                      {"spurious", s.spurious},
                      {"bias_type", s.bias_type},
                      {"mean_shrink_pct", s.mean_shrink_pct},
                      {"mean_excess_shrink_pct", s.mean_excess_shrink_pct},
                      {"null_" + style.noun + "s", s.null_cases},
                      {"null_claims", s.null_claims},
                      {"outside_" + style.noun + "s", s.outside_cases},
                      {"outside_claims", s.outside_claims},
                      {"aims_met", s.aims_met()}};
  if (style.shows_nearest) {
    j["partly_explained_in_library"] = s.partly_explained_in_library;
    j["partly_top_correct"] = s.partly_top_correct;
    j["unexplained_in_library"] = s.unexplained_in_library;
    j["nearest_correct"] = s.nearest_correct;
    j["null_none"] = s.null_none;
  }
  if (!s.classes.empty()) {
    nlohmann::json classes = nlohmann::json::array();
    for (const BlindClassRow& row : s.classes) {
      classes.push_back({{"class", row.name},
                         {"pairs", row.pairs},
                         {"top_correct", row.top_correct},
                         {"named", row.named},
                         {"bias_pairs", row.bias_pairs},
                         {"mean_excess_shrink_pct", row.mean_excess_shrink_pct},
                         {"alone", row.alone},
                         {"alone_top_correct", row.alone_top},
                         {"shared", row.shared},
                         {"shared_top_correct", row.shared_top},
                         {"shared_named", row.shared_named}});
    }
    j["by_class"] = classes;
  }
  nlohmann::json by_effects = nlohmann::json::array();
  for (const BlindEffectsRow& row : s.by_effects) {
    by_effects.push_back(
        {{"effects", row.effects},
         {"cases", row.cases},
         {"explained", row.explained},
         {"top_correct", row.top_correct},
         {"all_found", row.all_found},
         {"top_among_indistinguishable", row.top_among_indistinguishable},
         {"all_among_indistinguishable", row.all_among_indistinguishable},
         {"bias_cases", row.bias_cases},
         {"mean_excess_shrink_pct", row.mean_excess_shrink_pct},
         {"explained_bias_cases", row.explained_bias_cases},
         {"mean_explained_excess_shrink_pct", row.mean_explained_excess_shrink_pct}});
  }
  j["by_effects"] = by_effects;
  return j;
}

}  // namespace

std::vector<std::string> blind_summary_lines(const BlindStyle& style, const BlindSummary& s) {
  const std::string& noun = style.noun;
  const std::string& item = style.item;
  std::vector<std::string> lines = {
      fmt::format("{}: {}/{} in-library {}s ({}); aim >= {} %: {}", style.top_label, s.top_correct,
                  s.in_library, noun, percent(s.top_correct, s.in_library), style.aims.top_pct,
                  s.top_aim_met ? "met" : "MISSED"),
      fmt::format("all true {} named: {}/{} ({}); {} named that were not there: {}", style.items,
                  s.all_found, s.in_library, percent(s.all_found, s.in_library), style.items,
                  s.spurious)};
  if (style.shows_nearest) {
    lines.push_back(
        fmt::format("partly explained in-library {}s: {}; of them the first {} named "
                    "was a true one in {}",
                    noun, s.partly_explained_in_library, item, s.partly_top_correct));
    lines.push_back(
        fmt::format("unexplained in-library {}s: {}; of them the nearest {} was a true one in {}",
                    noun, s.unexplained_in_library, item, s.nearest_correct));
  }
  lines.push_back(
      fmt::format("mean held-out shrink, bias-type {}s ({}): {:.1f} % of the gap "
                  "above the noise (aim >= {:g} %: {}); {:.1f} % of the gap RMS with "
                  "the noise left in",
                  noun, s.bias_type, s.mean_excess_shrink_pct, style.aims.excess_shrink_pct,
                  s.shrink_aim_met ? "met" : "MISSED", s.mean_shrink_pct));
  for (std::string& line : style.kind_lines(s)) lines.push_back(std::move(line));
  return lines;
}

std::string blind_terminal_report(const std::string& header, const BlindStyle& style,
                                  const std::vector<BlindRow>& rows, const BlindSummary& summary) {
  std::string text = header + "\n" + terminal_table(style, rows);
  if (!summary.classes.empty()) text += "\n" + class_table(summary) + "\n";
  if (style.extra_tables) text += style.extra_tables(summary) + "\n";
  for (const std::string& line : blind_summary_lines(style, summary)) text += line + "\n";
  return text;
}

std::string blind_markdown(const std::string& header, const BlindStyle& style,
                           const std::vector<BlindRow>& rows, const BlindSummary& summary) {
  std::string md = header + "\n\n" + markdown_table(style, rows) + "\n";
  if (!summary.classes.empty()) {
    md +=
        "By class (in-library " + style.noun + "s that hold it):\n\n" + class_table(summary) + "\n";
  }
  if (style.extra_tables) md += style.extra_tables(summary) + "\n";
  for (const std::string& line : blind_summary_lines(style, summary)) md += "- " + line + "\n";
  return md;
}

nlohmann::json blind_json(const SelftestOptions& options, const BlindStyle& style,
                          const std::vector<BlindRow>& rows, const BlindSummary& summary) {
  nlohmann::json j = style.run_json;
  j["generated_by"] = runtime::generated_by(
      options.only_case > 0
          ? fmt::format("{} --case {} --seed {}", style.command, options.only_case, options.seed)
          : fmt::format("{} --{}s {} --seed {}", style.command, style.noun, summary.cases,
                        options.seed));
  nlohmann::json cases = nlohmann::json::array();
  for (const BlindRow& row : rows) cases.push_back(case_json(style, row));
  j[style.noun + "s"] = cases;
  j["summary"] = summary_json(style, summary);
  return j;
}

nlohmann::json findings_json(const std::vector<EffectFinding>& findings, bool heldout_rms,
                             bool inclusion) {
  nlohmann::json list = nlohmann::json::array();
  for (const EffectFinding& f : findings) {
    nlohmann::json item = {{"name", f.name}, {"params", f.params}};
    if (heldout_rms) item["heldout_rms_after"] = f.heldout_rms_after;
    if (inclusion) item["inclusion"] = f.inclusion;
    list.push_back(item);
  }
  return list;
}

nlohmann::json claims_json(const std::vector<EffectFinding>& effects,
                           const std::vector<std::string>& claimed,
                           const std::vector<bool>& right) {
  nlohmann::json claims = nlohmann::json::array();
  for (std::size_t k = 0; k < claimed.size() && k < effects.size() && k < right.size(); ++k) {
    claims.push_back(
        {{"class", claimed[k]}, {"confidence", effects[k].confidence}, {"right", right[k]}});
  }
  return claims;
}

}  // namespace flange::diagnose
