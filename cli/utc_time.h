// SPDX-License-Identifier: MIT
// A session's start time on the command line: ISO 8601 in UTC, YYYY-MM-DDThh:mm:ss[.f...]Z
// (e.g. 2026-11-21T09:30:00Z), as a DAQ's file header or a lab book gives it.
#pragma once

#include <string>

namespace flange::cli {

// Seconds since 1970-01-01T00:00:00Z. Throws host::InputError naming `option`, the text and the
// form and ranges expected.
double parse_utc_time(const std::string& text, const std::string& option);

// `utc_s` (seconds since 1970-01-01T00:00:00Z, >= 0) as parse_utc_time reads it, to the
// millisecond: YYYY-MM-DDThh:mm:ss.fffZ.
std::string format_utc_time(double utc_s);

}  // namespace flange::cli
