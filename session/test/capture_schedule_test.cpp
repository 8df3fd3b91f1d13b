// Which frames save PNGs (session/capture_schedule.h): capture.times_s and
// capture.every_s under ig run's nearest-frame rule and ig serve's
// first-frame-at-or-after rule.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "session/capture_schedule.h"

namespace {

using ig::session::CaptureSchedule;

// The frames (of `frames` at `step`) that capture under the nearest-frame rule.
std::vector<int> captured_frames(CaptureSchedule s, int frames, double step) {
  std::vector<int> out;
  for (int k = 0; k < frames; ++k)
    if (s.take(k * step)) out.push_back(k);
  return out;
}

TEST(CaptureSchedule, ListedTimesGoToTheNearestFrame) {
  const double step = 0.0166667;
  CaptureSchedule s({0.0, 6.0, 12.0, 6.0}, 0.0, CaptureSchedule::nearest_frame_tolerance(step));
  // round(6 / 0.0166667) = 360, round(12 / 0.0166667) = 720: what ig run always captured.
  EXPECT_EQ(captured_frames(s, 721, step), (std::vector<int>{0, 360, 720}));
}

TEST(CaptureSchedule, HalfAStepGoesToTheLaterFrame) {
  CaptureSchedule s({0.05, 0.149}, 0.0, CaptureSchedule::nearest_frame_tolerance(0.1));
  EXPECT_EQ(captured_frames(s, 5, 0.1), (std::vector<int>{1}));  // 0.05 -> 1 (tie), 0.149 -> 1
  CaptureSchedule t({0.151}, 0.0, CaptureSchedule::nearest_frame_tolerance(0.1));
  EXPECT_EQ(captured_frames(t, 5, 0.1), (std::vector<int>{2}));
}

TEST(CaptureSchedule, EveryNSecondsFromZero) {
  CaptureSchedule s({}, 0.5, CaptureSchedule::nearest_frame_tolerance(0.1));
  EXPECT_EQ(captured_frames(s, 21, 0.1), (std::vector<int>{0, 5, 10, 15, 20}));
  // A period that is no multiple of the step: 0, 0.25 -> 0.3 (tie up), 0.5, 0.75 -> 0.8, 1.0.
  CaptureSchedule q({}, 0.25, CaptureSchedule::nearest_frame_tolerance(0.1));
  EXPECT_EQ(captured_frames(q, 11, 0.1), (std::vector<int>{0, 3, 5, 8, 10}));
}

TEST(CaptureSchedule, ListedAndPeriodicTogetherCaptureOnceAFrame) {
  CaptureSchedule s({0.5, 0.7}, 1.0, CaptureSchedule::nearest_frame_tolerance(0.1));
  EXPECT_EQ(captured_frames(s, 21, 0.1), (std::vector<int>{0, 5, 7, 10, 20}));
}

TEST(CaptureSchedule, FirstFrameAtOrAfterWithoutTolerance) {
  // ig serve: irregular frame times; a frame serves every time it passed.
  CaptureSchedule s({0.0, 0.3}, 1.0, 0.0);
  EXPECT_TRUE(s.take(0.02));   // 0
  EXPECT_FALSE(s.take(0.29));
  EXPECT_TRUE(s.take(0.31));   // 0.3
  EXPECT_FALSE(s.take(0.99));
  EXPECT_TRUE(s.take(1.0));    // 1 (at, not only after)
  EXPECT_TRUE(s.take(7.5));    // 2..7 after a pause: one capture
  EXPECT_FALSE(s.take(7.6));
  EXPECT_TRUE(s.take(8.0));
}

TEST(CaptureSchedule, PendingNamesWhatNoFrameReached) {
  CaptureSchedule s({0.0, 6.0, 12.0}, 0.0, CaptureSchedule::nearest_frame_tolerance(0.1));
  for (int k = 0; k < 5; ++k) s.take(k * 0.1);
  EXPECT_EQ(s.pending(12.0, 10), (std::vector<double>{6.0, 12.0}));
  EXPECT_EQ(s.pending_count(12.0), 2u);
  EXPECT_EQ(s.pending(12.0, 1), (std::vector<double>{6.0}));

  CaptureSchedule e({2.5, 3.0}, 1.0, 0.0);
  e.take(1.5);  // served 0 and 1
  EXPECT_EQ(e.pending(4.0, 10), (std::vector<double>{2.0, 2.5, 3.0, 4.0}));  // 3 listed and periodic: once
  EXPECT_EQ(e.pending_count(4.0), 4u);
  EXPECT_EQ(e.pending_count(1e6), 2u + 999999u - 1u);  // 2.5, and 2, 3, ..., 1e6 (3 once)
}

TEST(CaptureSchedule, NothingScheduledNeverCaptures) {
  CaptureSchedule s({}, 0.0, 0.05);
  EXPECT_TRUE(captured_frames(s, 100, 0.1).empty());
  EXPECT_EQ(s.pending_count(1e9), 0u);
}

}  // namespace
