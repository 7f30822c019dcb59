// SPDX-License-Identifier: MIT
// Session start times on the command line (cli/utc_time.h): the seconds since 1970 of a UTC time,
// and a one-line refusal naming the option, the text and the form for anything else.
#include "utc_time.h"

#include <gtest/gtest.h>

#include <string>

#include "input_error.h"

namespace flange::cli {
namespace {

TEST(UtcTime, KnownInstants) {
  EXPECT_DOUBLE_EQ(parse_utc_time("1970-01-01T00:00:00Z", "--t"), 0.0);
  EXPECT_DOUBLE_EQ(parse_utc_time("2026-01-01T00:00:00Z", "--t"), 1767225600.0);
  EXPECT_DOUBLE_EQ(parse_utc_time("2024-02-29T23:59:59Z", "--t"), 1709251199.0);
  EXPECT_DOUBLE_EQ(parse_utc_time("2026-11-21T09:30:00.25Z", "--t"), 1795253400.25);
}

TEST(UtcTime, DifferencesAreExactAcrossMonthsAndLeapDays) {
  EXPECT_DOUBLE_EQ(
      parse_utc_time("2024-03-01T00:00:00Z", "--t") - parse_utc_time("2024-02-28T12:00:00Z", "--t"),
      1.5 * 86400.0);
}

TEST(UtcTime, AnythingElseIsRefusedNamingTheOptionAndTheForm) {
  for (const std::string bad :
       {"", "2026-11-21", "2026-11-21T09:30:00", "2026-11-21T09:30:00+01:00",
        "2026-11-21 09:30:00Z", "2026-02-30T00:00:00Z", "2026-11-21T24:00:00Z",
        "2026-11-21T09:60:00Z", "1969-12-31T23:59:59Z", "2026-11-21T09:30:00.Z",
        "2026-11-21T09:30:00.5xZ", "20261121T093000Z"}) {
    try {
      parse_utc_time(bad, "--holdout-start");
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const host::InputError& error) {
      const std::string what = error.what();
      EXPECT_EQ(what.rfind("--holdout-start: '" + bad + "' is not a UTC time", 0), 0) << what;
      EXPECT_NE(what.find("YYYY-MM-DDThh:mm:ss[.fff]Z"), std::string::npos) << what;
    }
  }
}

}  // namespace
TEST(UtcTime, FormattedTimesReadBackToTheMillisecond) {
  EXPECT_EQ(format_utc_time(0.0), "1970-01-01T00:00:00.000Z");
  EXPECT_EQ(format_utc_time(1767225600.0), "2026-01-01T00:00:00.000Z");
  for (const double t : {1767225600.0 + 6944.115, 1.7e9 + 86399.9996, 951782400.5}) {
    EXPECT_NEAR(parse_utc_time(format_utc_time(t), "--real-start"), t, 5e-4) << format_utc_time(t);
  }
}

}  // namespace flange::cli
