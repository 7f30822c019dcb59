// SPDX-License-Identifier: MIT
// diagnosis.json, the summary text and the HTML report (gnuplot SVGs) of `flange diagnose`.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "diagnosis_detail.h"

namespace flange::diagnose {

nlohmann::ordered_json diagnosis_json(const DiagnosisResult& result, const std::string& real,
                                      const std::string& heldout);
// The verdict first, then where, which and how far, in a few lines.
std::string diagnosis_summary(const DiagnosisResult& result);
// Writes report.html, region.svg, spectrum.svg, time.svg and heldout.svg into `dir`.
void write_diagnosis_report(const std::filesystem::path& dir, const DiagnosisResult& result,
                            const std::string& title);

}  // namespace flange::diagnose
