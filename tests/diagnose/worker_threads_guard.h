// SPDX-License-Identifier: MIT
// The diagnosis's worker threads (diagnose/data/base/parallel_work.h) set for one test and put
// back after it, so that a test of how work is shared over the cores leaves the next as it found it.
#pragma once

#include "parallel_work.h"

namespace flange::diagnose::testing {

class WorkerThreads {
 public:
  explicit WorkerThreads(int threads) : before_(worker_threads()) { set_worker_threads(threads); }
  ~WorkerThreads() { set_worker_threads(before_); }
  WorkerThreads(const WorkerThreads&) = delete;
  WorkerThreads& operator=(const WorkerThreads&) = delete;

 private:
  int before_;
};

}  // namespace flange::diagnose::testing
