// Trimming the heap gives freed pages back: resident memory held in malloc's
// free lists after many small blocks are freed drops when trimmed, and the
// trims are paced.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <vector>

#include "session/heap_trim.h"
#include "session/process_memory.h"

namespace {

double rss_mb() { return ig::session::process_memory().value("rss_mb", 0.0); }

TEST(HeapTrim, FreedSmallBlocksGoBackToTheSystem) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  GTEST_SKIP() << "A sanitizer's allocator replaces malloc: nothing of the C library's heap to trim";
#endif
  // 96 MB in 64 KB blocks (under malloc's mmap threshold: heap memory),
  // touched, then all freed but one allocated after them, which keeps the
  // top of the heap in use so malloc cannot shrink it on its own.
  std::vector<std::unique_ptr<char[]>> blocks;
  for (int k = 0; k < 1536; ++k) {
    blocks.emplace_back(new char[64 * 1024]);
    std::memset(blocks.back().get(), 1, 64 * 1024);
  }
  auto pin = std::make_unique<char[]>(4096);
  std::memset(pin.get(), 1, 4096);
  const double full = rss_mb();
  blocks.clear();
  const double freed = rss_mb();
  EXPECT_GT(freed, full - 48.0) << "malloc kept most of the freed pages (without a trim)";
  ig::session::HeapTrim trim(10.0);
  trim.trim();
  EXPECT_LT(rss_mb(), freed - 64.0);
  const auto s = trim.summary();
  EXPECT_EQ(s["trims"], 1);
  EXPECT_GT(s["released_mb"].get<double>(), 64.0);
}

TEST(HeapTrim, AtMostOnceEveryPeriod) {
  ig::session::HeapTrim trim(10.0);
  EXPECT_TRUE(trim.maybe_trim(100.0));
  EXPECT_FALSE(trim.maybe_trim(105.0));
  EXPECT_FALSE(trim.maybe_trim(109.9));
  EXPECT_TRUE(trim.maybe_trim(110.0));
  EXPECT_EQ(trim.summary()["trims"], 2);
}

}  // namespace
