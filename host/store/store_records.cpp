// SPDX-License-Identifier: MIT
#include "store_records.h"

namespace flange::host {

const char* session_kind_name(SessionKind kind) {
  return kind == SessionKind::kBench ? "bench" : "service";
}

int default_channel(const WheelKey& wheel) {
  return 2 * (wheel.axle - 1) + (wheel.side == "right" ? 1 : 0);
}

}  // namespace flange::host
