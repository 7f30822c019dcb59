// SPDX-License-Identifier: MIT
#include "iir_sample_vector.h"

#include <stdexcept>

#include "iir_sample_model.h"

namespace flange::model::vector {

bool supported(const CoreConfig&) { return false; }

void run(const CoreConfig&, std::int64_t*, const std::int32_t*, SampleResult*, std::size_t) {
  throw std::logic_error("vector kernel unavailable");
}

}  // namespace flange::model::vector
