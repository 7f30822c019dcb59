// SPDX-License-Identifier: MIT
// `flange diagnose` keeps freed memory in the heap for its next block (cli/diagnose_memory.h):
// a large block is not a mapping of its own, and freeing it does not shrink the heap. Its own
// binary: the policy holds for the rest of the process once set.
#include "diagnose_memory.h"

#include <gtest/gtest.h>
#include <malloc.h>

#include <cstdlib>
#include <cstring>

#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || \
    __has_feature(memory_sanitizer)
#define FLANGE_OWN_ALLOCATOR 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define FLANGE_OWN_ALLOCATOR 1
#endif

namespace flange::cli {
namespace {

TEST(DiagnoseMemory, ALargeBlockComesFromTheHeapAndStaysThereOnceFreed) {
#ifdef FLANGE_OWN_ALLOCATOR
  GTEST_SKIP() << "a sanitizer's allocator replaces glibc's malloc, which mallopt sets";
#endif
  keep_freed_memory_for_reuse();
  constexpr std::size_t kBlock = std::size_t{96} << 20;  // over malloc's largest mmap threshold
  const struct mallinfo2 before = mallinfo2();
  auto* block = static_cast<char*>(std::malloc(kBlock));
  ASSERT_NE(block, nullptr);
  std::memset(block, 1, kBlock);
  const struct mallinfo2 held = mallinfo2();
  EXPECT_EQ(held.hblkhd, before.hblkhd) << "the block was mapped on its own";
  EXPECT_GE(held.arena, before.arena + kBlock);
  std::free(block);
  const struct mallinfo2 freed = mallinfo2();
  EXPECT_EQ(freed.arena, held.arena) << "the heap was trimmed on free";
  EXPECT_GE(freed.fordblks, kBlock);
  // The next block of that size is served from the freed one: the heap does not grow.
  void* again = std::malloc(kBlock);
  ASSERT_NE(again, nullptr);
  EXPECT_EQ(mallinfo2().arena, held.arena);
  std::free(again);
}

}  // namespace
}  // namespace flange::cli
