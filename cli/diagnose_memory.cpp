// SPDX-License-Identifier: MIT
#include "diagnose_memory.h"

#include <malloc.h>

#include <limits>

namespace flange::cli {

void keep_freed_memory_for_reuse() {
  // One arena: with one per thread, the columns a free family frees on one core are not
  // reused by the next family on the other, and the peak of a 45-minute 100 Hz pair grows
  // by about a tenth; its allocations are few and large, so the threads rarely wait on it.
  mallopt(M_ARENA_MAX, 1);
  // No block is mapped on its own (mallopt caps M_MMAP_THRESHOLD at 32 MB, and the largest
  // matrices are larger), and the heap's free top is never returned, so a block freed is
  // the next one's pages, already faulted in. The peak stays the diagnosis's own: it frees
  // what it is done with, and the heap serves the next block from it.
  mallopt(M_MMAP_MAX, 0);
  mallopt(M_TRIM_THRESHOLD, std::numeric_limits<int>::max());
}

}  // namespace flange::cli
