// SPDX-License-Identifier: MIT
// What `flange diagnose --selftest --reality third` shows beyond the harness's report
// (blind_report.h): its seed line, the table by class split into pairs that hold the class alone
// and with others, the table by number of true classes, and the aims (third_aims()).
#pragma once

#include <string>

#include "blind_report.h"
#include "third_selftest.h"

namespace flange::diagnose {

std::string third_selftest_header(const BlindSummary& summary, const SelftestOptions& options);
BlindStyle third_selftest_style(const SelftestOptions& options);
// The aims' lines (also in the report's tables section).
std::vector<std::string> third_aims_lines(const ThirdAims& aims);

}  // namespace flange::diagnose
