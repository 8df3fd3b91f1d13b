// HeightPyramid (terrain/height_pyramid.h): every level bounds the heights
// it covers, checked against the samples; compact storage; bad input.
#include <gtest/gtest.h>

#include "terrain/test/ray_cast_test_support.h"

namespace {

using namespace ray_cast_test;

// ------------------------------------------------------------------ pyramid

void check_pyramid(int w, int h) {
  SCOPED_TRACE(testing::Message() << w << "x" << h);
  const Heightfield hf = random_hf(w, h, 1.0, 1.0, unsigned(w * 1000 + h));
  const HeightPyramid pyr(hf);
  ASSERT_FALSE(pyr.empty());
  EXPECT_EQ(pyr.cells_x(), w - 1);
  EXPECT_EQ(pyr.cells_y(), h - 1);
  ASSERT_GE(pyr.num_levels(), 1);
  const float tight = 4.0f * (hf.max_m - hf.min_m) / 65000.0f + 1e-3f;
  EXPECT_EQ(pyr.level_width(pyr.num_levels() - 1), 1);
  EXPECT_EQ(pyr.level_height(pyr.num_levels() - 1), 1);
  for (int k = 0; k < pyr.num_levels(); ++k) {
    if (k > 0) {
      EXPECT_EQ(pyr.level_width(k), (pyr.level_width(k - 1) + 1) / 2);
      EXPECT_EQ(pyr.level_height(k), (pyr.level_height(k - 1) + 1) / 2);
      EXPECT_TRUE(pyr.level_width(k - 1) > 1 || pyr.level_height(k - 1) > 1);
    }
    for (int nj = 0; nj < pyr.level_height(k); ++nj)
      for (int ni = 0; ni < pyr.level_width(k); ++ni) {
        // Samples covered: cells [ni<<k, min((ni+1)<<k, cells)) plus one.
        const int i0 = ni << k, i1 = std::min((ni + 1) << k, w - 1);
        const int j0 = nj << k, j1 = std::min((nj + 1) << k, h - 1);
        ASSERT_LT(i0, i1);
        ASSERT_LT(j0, j1);
        float lo = kInf, hi = -kInf;
        for (int j = j0; j <= j1; ++j)
          for (int i = i0; i <= i1; ++i) {
            lo = std::min(lo, hf.at(i, j));
            hi = std::max(hi, hf.at(i, j));
          }
        const auto mm = pyr.node(k, ni, nj);
        if (k <= 1) {  // read from the heights: exact
          ASSERT_EQ(mm.lo, lo) << "level " << k << " node " << ni << "," << nj;
          ASSERT_EQ(mm.hi, hi) << "level " << k << " node " << ni << "," << nj;
        } else {  // 16-bit codes: bounds, loose by a few steps of range / 65000 at most
          ASSERT_LE(mm.lo, lo) << "level " << k << " node " << ni << "," << nj;
          ASSERT_GE(mm.hi, hi) << "level " << k << " node " << ni << "," << nj;
          ASSERT_LE(lo - mm.lo, tight) << "level " << k << " node " << ni << "," << nj;
          ASSERT_LE(mm.hi - hi, tight) << "level " << k << " node " << ni << "," << nj;
        }
      }
  }
  EXPECT_EQ(pyr.root().lo, hf.min_m);
  EXPECT_EQ(pyr.root().hi, hf.max_m);
}

TEST(HeightPyramid, LevelsMatchBruteForce) {
  for (auto [w, h] : {std::pair{2, 2}, {3, 2}, {2, 3}, {3, 3}, {5, 3}, {17, 9}, {33, 33}, {65, 47}, {100, 7},
                      {2, 100}, {130, 3}})
    check_pyramid(w, h);
}

// The pyramid must stay within about 2 bytes per sample (levels 0
// and 1 read from the heights, levels >= 2 as 16-bit codes), and every node must
// still bound the heights of the samples it covers, whatever the range
// (Sierra-like thousands of metres, a nearly flat field far from 0). Strips
// 1 or 2 cells tall are exempt: their levels are padded to 2x2 blocks.
TEST(HeightPyramid, CompactAtMostTwoBytesPerSampleAndBounds) {
  for (auto [w, h, base, amp] : {std::tuple{1025, 1025, 0.0f, 4500.0f}, {513, 700, 8000.0f, 0.01f},
                                 {257, 5, -400.0f, 50.0f}}) {
    SCOPED_TRACE(testing::Message() << w << "x" << h << " base " << base << " amp " << amp);
    std::mt19937 rng(unsigned(w + h));
    std::uniform_real_distribution<float> u(0.f, 1.f);
    const Heightfield hf = make_hf(w, h, 30.0, 30.0, [&](int i, int j) {
      return base + amp * float(0.5 + 0.3 * std::sin(i * 0.01) * std::cos(j * 0.013) + 0.2 * u(rng));
    });
    const HeightPyramid pyr(hf);
    const double bytes_per_sample = double(pyr.memory_bytes()) / (double(w) * h);
    std::printf("%dx%d: %zu bytes, %.3f bytes per sample\n", w, h, pyr.memory_bytes(), bytes_per_sample);
    EXPECT_LE(bytes_per_sample, 2.0);
    for (int k = 0; k < pyr.num_levels(); ++k)
      for (int nj = 0; nj < pyr.level_height(k); ++nj)
        for (int ni = 0; ni < pyr.level_width(k); ++ni) {
          const int i1 = std::min((ni + 1) << k, w - 1), j1 = std::min((nj + 1) << k, h - 1);
          float lo = std::numeric_limits<float>::infinity(), hi = -lo;
          for (int j = nj << k; j <= j1; ++j)
            for (int i = ni << k; i <= i1; ++i) {
              lo = std::min(lo, hf.at(i, j));
              hi = std::max(hi, hf.at(i, j));
            }
          const auto mm = pyr.node(k, ni, nj);
          ASSERT_LE(mm.lo, lo) << "level " << k << " node " << ni << "," << nj;
          ASSERT_GE(mm.hi, hi) << "level " << k << " node " << ni << "," << nj;
        }
  }
}

TEST(HeightPyramid, DegenerateAndInvalid) {
  Heightfield hf = make_hf(2, 2, 1, 1, [](int i, int j) { return float(i + 2 * j); });
  const HeightPyramid p(hf);
  EXPECT_EQ(p.num_levels(), 1);
  EXPECT_EQ(p.root().lo, 0.f);
  EXPECT_EQ(p.root().hi, 3.f);

  const HeightPyramid empty(make_hf(1, 5, 1, 1, [](int, int) { return 0.f; }));
  EXPECT_TRUE(empty.empty());
  EXPECT_EQ(empty.num_levels(), 0);

  hf.heights.pop_back();
  EXPECT_THROW(HeightPyramid{hf}, std::invalid_argument);
}

}  // namespace
