// SPDX-License-Identifier: MIT
#include "wheel_history.h"

#include <chrono>
#include <cstdio>
#include <stdexcept>

namespace flange::host {

double day_of_iso_time(const std::string& text) {
  int y = 0, mo = 0, d = 0, h = 0, mi = 0;
  double s = 0.0;
  const int fields = std::sscanf(text.c_str(), "%4d-%2d-%2dT%2d:%2d:%lf", &y, &mo, &d, &h, &mi, &s);
  using namespace std::chrono;
  const year_month_day date{year{y}, month{static_cast<unsigned>(mo)},
                            std::chrono::day{static_cast<unsigned>(d)}};
  if (fields < 3 || !date.ok() || h < 0 || h > 23 || mi < 0 || mi > 59 || s < 0.0 || s >= 61.0) {
    throw std::invalid_argument("'" + text + "' is not a UTC time YYYY-MM-DDThh:mm:ssZ");
  }
  return static_cast<double>(sys_days{date}.time_since_epoch().count()) +
         (h * 3600.0 + mi * 60.0 + s) / 86400.0;
}

}  // namespace flange::host
