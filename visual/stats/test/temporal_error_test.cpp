// Temporal error (visual/stats/temporal_error.*) on synthetic luma images
// whose answers are known by construction. No GL.
#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>

#include "stats/temporal_error.h"

namespace {

using ig::stats::LumaImage;
using ig::stats::temporal_error;

// A horizontal ramp (luma x * step + offset) that moves `shift` columns to
// the right: what a camera panning over a smooth scene gives.
LumaImage ramp(int w, int h, double step, double offset, int shift = 0) {
  LumaImage f{w, h, std::vector<float>(std::size_t(w) * h)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) f.luma[std::size_t(y) * w + x] = float((x - shift) * step + offset);
  return f;
}

// `img` with the rectangle [x0, x1) x [y0, y1) raised by `amount` levels: a
// patch of terrain whose mesh changed.
LumaImage with_patch(LumaImage img, int x0, int x1, int y0, int y1, float amount) {
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) img.luma[std::size_t(y) * img.width + x] += amount;
  return img;
}

TEST(TemporalError, MethodMovingExactlyAsTheReferenceScoresZero) {
  // The method differs from the reference by a constant offset (a static
  // error), but changes exactly as it does: no popping.
  const auto rb = ramp(40, 30, 2.0, 10.0), rn = ramp(40, 30, 2.0, 10.0, 3);
  const auto mb = ramp(40, 30, 2.0, 25.0), mn = ramp(40, 30, 2.0, 25.0, 3);
  const auto e = temporal_error(mb, mn, rb, rn);
  EXPECT_EQ(e.mean, 0.0);
  EXPECT_DOUBLE_EQ(e.reference_change, 6.0);
  EXPECT_DOUBLE_EQ(e.method_change, 6.0);
}

TEST(TemporalError, AStillViewWithAStillMethodScoresZero) {
  const auto r = ramp(16, 8, 1.0, 0.0), m = with_patch(r, 2, 6, 2, 6, 40.0f);
  const auto e = temporal_error(m, m, r, r);
  EXPECT_EQ(e.mean, 0.0);
  EXPECT_EQ(e.method_change, 0.0);
  EXPECT_EQ(e.reference_change, 0.0);
}

TEST(TemporalError, APatchThatPopsWhereTheReferenceDoesNotScoresItsAreaTimesItsJump) {
  // The reference pans; the method pans too, and a 10 x 6 patch jumps by 30
  // levels between the frames: 60 of 1200 pixels off by 30 -> 1.5 levels.
  const auto rb = ramp(40, 30, 2.0, 10.0), rn = ramp(40, 30, 2.0, 10.0, 3);
  const auto mn = with_patch(rn, 5, 15, 4, 10, 30.0f);
  const auto e = temporal_error(rb, mn, rb, rn);
  EXPECT_DOUBLE_EQ(e.mean, 60.0 * 30.0 / 1200.0);
  EXPECT_GT(e.mean, 0.0);
}

TEST(TemporalError, IsLinearInTheJumpAndBlindToItsSign) {
  const auto r = ramp(20, 10, 1.0, 50.0), rn = ramp(20, 10, 1.0, 50.0, 1);
  const double e1 = temporal_error(r, with_patch(rn, 0, 5, 0, 5, 10.0f), r, rn).mean;
  const double e2 = temporal_error(r, with_patch(rn, 0, 5, 0, 5, 20.0f), r, rn).mean;
  const double e_neg = temporal_error(r, with_patch(rn, 0, 5, 0, 5, -10.0f), r, rn).mean;
  EXPECT_GT(e1, 0.0);
  EXPECT_NEAR(e2, 2.0 * e1, 1e-9);
  EXPECT_NEAR(e_neg, e1, 1e-9);
}

TEST(TemporalError, AMethodThatStandsStillWhileTheReferenceMovesIsWrongToo) {
  // A frozen image is as wrong as one that changes where it should not.
  const auto rb = ramp(30, 10, 2.0, 0.0), rn = ramp(30, 10, 2.0, 0.0, 2);
  const auto e = temporal_error(rb, rb, rb, rn);
  EXPECT_DOUBLE_EQ(e.mean, e.reference_change);
  EXPECT_DOUBLE_EQ(e.mean, 4.0);
  EXPECT_EQ(e.method_change, 0.0);
}

TEST(TemporalError, LuminanceUsesRec709WeightsOn8BitLevelsAndIgnoresAlpha) {
  ig::stats::FrameImage f;
  f.width = 3;
  f.height = 1;
  f.depth.assign(3, 0.0f);
  f.rgba = {255, 0, 0, 7, 0, 255, 0, 200, 0, 0, 255, 0};
  const auto l = ig::stats::luminance(f);
  ASSERT_EQ(l.luma.size(), 3u);
  EXPECT_NEAR(l.luma[0], 0.2126 * 255, 1e-3);
  EXPECT_NEAR(l.luma[1], 0.7152 * 255, 1e-3);
  EXPECT_NEAR(l.luma[2], 0.0722 * 255, 1e-3);
}

TEST(TemporalError, MismatchedOrMalformedImagesThrow) {
  const auto a = ramp(8, 8, 1.0, 0.0), b = ramp(8, 7, 1.0, 0.0);
  EXPECT_THROW(temporal_error(a, a, a, b), std::invalid_argument);
  EXPECT_THROW(temporal_error(b, a, a, a), std::invalid_argument);
  EXPECT_THROW(temporal_error(LumaImage{}, LumaImage{}, LumaImage{}, LumaImage{}), std::invalid_argument);
  LumaImage short_buffer = a;
  short_buffer.luma.pop_back();
  EXPECT_THROW(temporal_error(a, short_buffer, a, a), std::invalid_argument);
  ig::stats::FrameImage bad;
  bad.width = 2;
  bad.height = 2;
  bad.rgba.resize(3);
  EXPECT_THROW(ig::stats::luminance(bad), std::invalid_argument);
}

}  // namespace
