// SPDX-License-Identifier: MIT
// Independent pieces of work spread over threads, each result kept in its own slot: the order
// the threads finish in changes nothing, so a run on one thread and on many give the same bits.
// The diagnosis uses it for a round's candidates, a lattice's points and the null replicas, the
// self-tests for their cases.
//
// Every thread that runs work holds one of the process's worker threads (set_worker_threads):
// a piece that spreads work of its own (a case of a self-test diagnosing, a candidate searching
// a lattice) adds threads only while some are free, so nested work shares the budget rather than
// multiplying it. A thread that waits for its helpers gives its place back while it waits, and a
// helper is taken on whenever one is free and pieces are left to claim, so a core freed by one
// piece of work is taken up by another already running.
#pragma once

#include <functional>
#include <vector>

namespace flange::diagnose {

// The most threads the process runs work on at once, 1 to 64 (default: the machine's cores).
// Set before any work starts (the command line's --jobs); 1: everything on the calling thread.
void set_worker_threads(int threads);
int worker_threads();

// Runs work(i) for every i in [0, count) on the calling thread and on as many helper threads as
// the budget frees, at most `jobs` threads for this call (0: no cap of its own). The first
// exception thrown by any work(i) is rethrown once all threads stop.
void run_in_parallel(int count, int jobs, const std::function<void(int)>& work);

// make(i) for every i in [0, count) over the worker threads, in index order. At most as many
// pieces are in flight as there are worker threads, so what they hold while they run (a free
// family's columns over every row) is that many pieces' worth, not count's.
template <typename T, typename Make>
std::vector<T> parallel_map(std::size_t count, const Make& make) {
  std::vector<T> out(count);
  run_in_parallel(static_cast<int>(count), 0, [&](int i) {
    out[static_cast<std::size_t>(i)] = make(static_cast<std::size_t>(i));
  });
  return out;
}

// first() and second() at once where a thread is free, else one after the other.
void run_both(const std::function<void()>& first, const std::function<void()>& second);

}  // namespace flange::diagnose
