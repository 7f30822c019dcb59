// SPDX-License-Identifier: MIT
#include "bench_records.h"

#include <ostream>

namespace flange::tb::sc {

std::ostream& operator<<(std::ostream& os, const InputRecord& record) {
  if (record.kind == InputRecord::Kind::kReset) return os << "reset @ " << record.cycle_start;
  return os << "strobe " << record.sample << " @ " << record.cycle_start;
}

std::ostream& operator<<(std::ostream& os, const OutputRecord& record) {
  return os << "output " << record.sample << " busy " << record.busy << " overrun "
            << record.overrun << " saturation " << record.saturation << " @ " << record.seen_at;
}

}  // namespace flange::tb::sc
