// SPDX-License-Identifier: MIT
#include "utc_time.h"

#include <fmt/format.h>

#include <charconv>
#include <chrono>
#include <cmath>
#include <string_view>

#include "input_error.h"

namespace flange::cli {
namespace {

// Reads exactly `digits` decimal digits at `pos`; false when they are not all there.
bool read_digits(std::string_view text, std::size_t pos, std::size_t digits, int& value) {
  if (pos + digits > text.size()) return false;
  const char* first = text.data() + pos;
  const auto [end, error] = std::from_chars(first, first + digits, value);
  return error == std::errc() && end == first + digits;
}

}  // namespace

double parse_utc_time(const std::string& text, const std::string& option) {
  const auto refuse = [&](const std::string& why) {
    return host::InputError(
        fmt::format("{}: '{}' is not a UTC time YYYY-MM-DDThh:mm:ss[.fff]Z (e.g. "
                    "2026-11-21T09:30:00Z): {}",
                    option, host::printable_excerpt(text), why));
  };
  const std::string_view s = text;
  int year = 0, month = 0, day = 0, hour = 0, minute = 0, second = 0;
  const bool layout = s.size() >= 20 && s[4] == '-' && s[7] == '-' && s[10] == 'T' &&
                      s[13] == ':' && s[16] == ':' && s.back() == 'Z' &&
                      read_digits(s, 0, 4, year) && read_digits(s, 5, 2, month) &&
                      read_digits(s, 8, 2, day) && read_digits(s, 11, 2, hour) &&
                      read_digits(s, 14, 2, minute) && read_digits(s, 17, 2, second);
  if (!layout) throw refuse("the layout differs (the time must end in Z, for UTC)");
  double fraction = 0.0;
  if (s.size() > 20) {  // a fraction of a second: '.' then digits, before the Z
    const std::string_view digits = s.substr(20, s.size() - 21);
    if (s[19] != '.' || digits.empty() ||
        digits.find_first_not_of("0123456789") != std::string_view::npos) {
      throw refuse("after the seconds only a fraction .fff and Z may follow");
    }
    std::from_chars(s.data() + 19, s.data() + s.size() - 1, fraction);
  } else if (s.size() != 20) {
    throw refuse("the layout differs");
  }
  const std::chrono::year_month_day date{std::chrono::year{year},
                                         std::chrono::month{static_cast<unsigned>(month)},
                                         std::chrono::day{static_cast<unsigned>(day)}};
  if (year < 1970 || !date.ok()) {
    throw refuse("the date must exist, from year 1970 (month 1 to 12, day within the month)");
  }
  if (hour > 23 || minute > 59 || second > 59) {
    throw refuse("hour 0 to 23, minute and second 0 to 59");
  }
  const auto days = std::chrono::sys_days{date}.time_since_epoch().count();
  return static_cast<double>(days) * 86400.0 + hour * 3600.0 + minute * 60.0 + second + fraction;
}

std::string format_utc_time(double utc_s) {
  const auto ms = static_cast<long long>(std::llround(utc_s * 1000.0));
  const std::chrono::sys_days day{std::chrono::days{ms / 86'400'000}};
  const std::chrono::year_month_day date{day};
  const long long in_day = ms % 86'400'000;
  return fmt::format("{:04d}-{:02d}-{:02d}T{:02d}:{:02d}:{:02d}.{:03d}Z",
                     static_cast<int>(date.year()), static_cast<unsigned>(date.month()),
                     static_cast<unsigned>(date.day()), in_day / 3'600'000, in_day / 60'000 % 60,
                     in_day / 1000 % 60, in_day % 1000);
}

}  // namespace flange::cli
