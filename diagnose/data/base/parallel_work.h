// SPDX-License-Identifier: MIT
// Independent pieces of work spread over threads, each result kept in its own slot: the order
// the threads finish in changes nothing, so a run on one thread and on many give the same bits.
// The diagnosis uses it for a round's candidates and the self-tests for their cases.
#pragma once

#include <functional>
#include <vector>

namespace flange::diagnose {

// Runs work(i) for every i in [0, count) over `jobs` threads (0: the machine's cores, never more
// than count). The first exception thrown by any work(i) is rethrown once all threads stop.
void run_in_parallel(int count, int jobs, const std::function<void(int)>& work);

// make(i) for every i in [0, count) over the machine's cores, in index order. At most as many
// pieces are in flight as there are cores, so what they hold while they run (a free family's
// columns over every row) is that many pieces' worth, not count's.
template <typename T, typename Make>
std::vector<T> parallel_map(std::size_t count, const Make& make) {
  std::vector<T> out(count);
  run_in_parallel(static_cast<int>(count), 0,
                  [&](int i) { out[static_cast<std::size_t>(i)] = make(static_cast<std::size_t>(i)); });
  return out;
}

}  // namespace flange::diagnose
