// The process's memory figures of summary.json move with what the process
// allocates and touches.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>

#include "session/process_memory.h"

namespace {

TEST(ProcessMemory, ResidentAndHeapInUseFollowAnAllocation) {
  const auto before = ig::session::process_memory();
  ASSERT_TRUE(before.contains("rss_mb"));
  ASSERT_TRUE(before.contains("peak_rss_mb"));
  constexpr size_t kBytes = size_t(64) << 20;
  auto block = std::make_unique<char[]>(kBytes);
  std::memset(block.get(), 1, kBytes);  // resident only once touched
  const auto during = ig::session::process_memory();
  EXPECT_GT(during["rss_mb"].get<double>() - before["rss_mb"].get<double>(), 60.0);
  EXPECT_GE(during["peak_rss_mb"].get<double>(), during["rss_mb"].get<double>());
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  GTEST_SKIP() << "A sanitizer's allocator replaces malloc: the C library's heap figures stay empty";
#endif
  EXPECT_GT(during["heap_in_use_mb"].get<double>() - before["heap_in_use_mb"].get<double>(), 63.9);
  block.reset();
  const auto after = ig::session::process_memory();
  EXPECT_LT(after["heap_in_use_mb"].get<double>(), during["heap_in_use_mb"].get<double>() - 63.9);
  EXPECT_GE(after["heap_free_mb"].get<double>(), 0.0);
}

}  // namespace
