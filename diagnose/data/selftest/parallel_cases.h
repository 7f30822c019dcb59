// SPDX-License-Identifier: MIT
// The blind checks' worker pool: independent cases spread over threads, results in case order.
#pragma once

#include <functional>

namespace flange::diagnose {

// Runs work(i) for every i in [0, count) over `jobs` threads (0: the machine's cores, never more
// than count). The first exception thrown by any work(i) is rethrown once all threads stop.
void run_in_parallel(int count, int jobs, const std::function<void(int)>& work);

}  // namespace flange::diagnose
