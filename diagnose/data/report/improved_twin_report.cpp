// SPDX-License-Identifier: MIT
#include "improved_twin_report.h"

#include <fmt/format.h>

#include "improved_twin_reasons.h"
#include "report_format.h"

namespace flange::diagnose {

nlohmann::ordered_json improved_twin_json(const ImprovedTwin& twin) {
  nlohmann::ordered_json findings = nlohmann::ordered_json::array();
  nlohmann::ordered_json not_held = nlohmann::ordered_json::array();
  for (const HeldFinding& f : twin.findings) {
    findings.push_back({{"name", f.name}, {"held_as", reasons::held_as_text(f.held_as)}, {"note", f.note}});
    if (f.held_as == HeldAs::kNotHeld) not_held.push_back(f.name);
  }
  nlohmann::ordered_json effects = nlohmann::ordered_json::array();
  for (const sim::EffectSettings& e : twin.twin.effects) effects.push_back(e.name);
  return {{"file", kImprovedTwinFile},
          {"summary", twin.summary},
          {"effects", effects},
          {"noise_voltage_std_v", twin.twin.noise.voltage_std_v},
          {"findings", findings},
          {"not_held", not_held},
          {"table_misfit_rms_v", twin.table_misfit_rms_v}};
}

std::string improved_twin_html(const ImprovedTwin& twin) {
  std::string html = fmt::format(
      "<h2>The improved twin</h2><p>{}: <code>{}</code>, beside diagnosis.json "
      "(<code>flange simulate --twin</code> and <code>flange diagnose --twin</code> take "
      "it).</p>\n",
      coeffs::html_escape(twin.summary), kImprovedTwinFile);
  if (twin.findings.empty()) return html;
  html += "<table><tr><th>finding</th><th>held as</th><th>how</th></tr>\n";
  for (const HeldFinding& f : twin.findings) {
    html += fmt::format("<tr><td>{}</td><td>{}</td><td style='text-align:left'>{}</td></tr>\n",
                        coeffs::html_escape(f.name), coeffs::html_escape(reasons::held_as_text(f.held_as)),
                        coeffs::html_escape(f.note));
  }
  return html + "</table>\n";
}

}  // namespace flange::diagnose
