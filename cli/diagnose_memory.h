// SPDX-License-Identifier: MIT
// How `flange diagnose` asks glibc's malloc to handle its memory.
#pragma once

namespace flange::cli {

// The diagnosis allocates and frees columns and matrices of megabytes to hundreds of
// megabytes, thousands of times a run. Left to malloc's defaults each one over the mmap
// threshold is a fresh mapping, its pages faulted in and zeroed by the kernel, and unmapped
// again on free: over a quarter of a 45-minute 100 Hz pair's CPU time went to the kernel
// (bench/diagnose_45min.sh, docs/benchmarks.md). This keeps every block in the heap, reused
// once freed and never given back before the process ends, with one arena for all threads.
// Call it before the diagnosis allocates; it changes no result.
void keep_freed_memory_for_reuse();

}  // namespace flange::cli
