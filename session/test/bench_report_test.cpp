// The matched-horizon-error table of ig bench (session/bench_report.*) on
// hand-made rows with known answers. No GL.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "session/bench_report.h"

namespace {

using ig::session::BenchRow;
using ig::session::MatchKind;

BenchRow row(const std::string& method, double knob, double error_px, double ms) {
  BenchRow r;
  r.method = method;
  if (knob >= 0) r.knob = ig::render::ErrorKnob{"k", "", knob};
  r.horizon_mean_px = error_px;
  r.frame_ms_median = ms;
  return r;
}

const ig::session::MatchedRow& find(const std::vector<ig::session::MatchedRow>& v, const std::string& m) {
  for (const auto& r : v)
    if (r.method == m) return r;
  throw std::runtime_error("no row for " + m);
}

TEST(BenchReport, MatchedErrorInterpolatesAlongEachSweep) {
  // twolevel: 4 px at 10 ms, 2 px at 20 ms (its default, the target), 1 px at 40 ms.
  // other: 6 px at 30 ms, 1 px at 80 ms -> at 2 px: 30 + (2 - 6) / (1 - 6) * 50 = 70 ms.
  std::vector<BenchRow> rows = {row("twolevel", 1, 4.0, 10.0), row("twolevel", 2, 2.0, 20.0),
                                row("twolevel", 3, 1.0, 40.0), row("other", 1, 6.0, 30.0),
                                row("other", 2, 1.0, 80.0),    row("reference", -1, 0.0, 500.0),
                                row("coarse", 1, 9.0, 5.0),    row("coarse", 2, 5.0, 7.0)};
  const auto m = ig::session::match_horizon_error(rows, 2.0);
  ASSERT_EQ(m.size(), 4u);
  EXPECT_EQ(find(m, "twolevel").kind, MatchKind::Measured);
  EXPECT_DOUBLE_EQ(find(m, "twolevel").frame_ms, 20.0);
  EXPECT_EQ(find(m, "other").kind, MatchKind::Interpolated);
  EXPECT_DOUBLE_EQ(find(m, "other").frame_ms, 70.0);
  EXPECT_DOUBLE_EQ(*find(m, "other").ratio, 3.5);
  // Always more accurate than the target: its cheapest point bounds it.
  EXPECT_EQ(find(m, "reference").kind, MatchKind::AtMost);
  EXPECT_DOUBLE_EQ(find(m, "reference").frame_ms, 500.0);
  EXPECT_DOUBLE_EQ(*find(m, "reference").ratio, 25.0);
  // Never that accurate: more than its most accurate point's time.
  EXPECT_EQ(find(m, "coarse").kind, MatchKind::NotReached);
  EXPECT_DOUBLE_EQ(find(m, "coarse").frame_ms, 7.0);
}

TEST(BenchReport, CurveCrossingTheTargetTwiceTakesTheFasterCrossing) {
  // 3 -> 1 px between 10 and 30 ms crosses 2 px at 20 ms; 1 -> 3 px between
  // 30 and 34 ms crosses it again at 32 ms.
  std::vector<BenchRow> rows = {row("m", 1, 3.0, 10.0), row("m", 2, 1.0, 30.0), row("m", 3, 3.0, 34.0)};
  const auto m = ig::session::match_horizon_error(rows, 2.0);
  EXPECT_EQ(m[0].kind, MatchKind::Interpolated);
  EXPECT_DOUBLE_EQ(m[0].frame_ms, 20.0);
  EXPECT_FALSE(m[0].ratio.has_value()) << "no twolevel row: no ratio";
}

TEST(BenchReport, NoRatioWhenTwolevelMissesTheTarget) {
  std::vector<BenchRow> rows = {row("twolevel", 1, 4.0, 10.0), row("twolevel", 2, 3.0, 20.0),
                                row("other", 1, 3.0, 5.0), row("other", 2, 0.5, 50.0)};
  const auto m = ig::session::match_horizon_error(rows, 1.0);
  EXPECT_EQ(find(m, "twolevel").kind, MatchKind::NotReached);
  EXPECT_EQ(find(m, "other").kind, MatchKind::Interpolated);
  EXPECT_DOUBLE_EQ(find(m, "other").frame_ms, 5.0 + (1.0 - 3.0) / (0.5 - 3.0) * 45.0);
  EXPECT_FALSE(find(m, "other").ratio.has_value());
}

}  // namespace

namespace {
TEST(BenchReport, MatchedErrorOnCpuTimeUsesTheCpuColumn) {
  // Same errors, CPU times unlike the wall times: the match follows the column asked for.
  std::vector<BenchRow> rows = {row("twolevel", 1, 2.0, 20.0), row("other", 1, 3.0, 10.0), row("other", 2, 1.0, 50.0)};
  rows[0].cpu_ms_median = 30.0;
  rows[1].cpu_ms_median = 20.0;
  rows[2].cpu_ms_median = 80.0;
  const auto wall = ig::session::match_horizon_error(rows, 2.0);
  const auto cpu = ig::session::match_horizon_error(rows, 2.0, &BenchRow::cpu_ms_median);
  EXPECT_DOUBLE_EQ(find(wall, "other").frame_ms, 30.0);
  EXPECT_DOUBLE_EQ(*find(wall, "other").ratio, 1.5);
  EXPECT_DOUBLE_EQ(find(cpu, "other").frame_ms, 50.0);
  EXPECT_DOUBLE_EQ(*find(cpu, "other").ratio, 50.0 / 30.0);
}

TEST(BenchReport, TemporalErrorAtTheTargetInTheMarkdown) {
  // other: temporal error 0.9 at 3 px, 0.1 at 1 px -> 0.5 at 2 px; coarse never reaches 2 px.
  std::vector<BenchRow> rows = {row("twolevel", 1, 2.0, 20.0), row("other", 1, 3.0, 10.0), row("other", 2, 1.0, 50.0),
                                row("coarse", 1, 8.0, 5.0)};
  rows[0].temporal_error_mean = 0.25;
  rows[1].temporal_error_mean = 0.9;
  rows[2].temporal_error_mean = 0.1;
  rows[3].temporal_error_mean = 3.0;
  const std::string path = ::testing::TempDir() + "bench_report_temporal.md";
  ig::session::BenchContext context;
  ig::session::write_bench_markdown(path, context, rows, 2.0, "test");
  std::ifstream in(path);
  const std::string md((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(md.find("temporal error at target"), std::string::npos);
  auto line_of = [&](const std::string& start) {
    const auto at = md.find("\n## Matched horizon error\n");
    const auto p = md.find("\n| " + start + " |", at);
    return p == std::string::npos ? std::string() : md.substr(p + 1, md.find('\n', p + 1) - p - 1);
  };
  EXPECT_NE(line_of("twolevel").find("| 0.250 |"), std::string::npos) << line_of("twolevel");
  EXPECT_NE(line_of("other").find("| 0.500 |"), std::string::npos) << line_of("other");
  EXPECT_NE(line_of("coarse").find("n/a (outside its sweep)"), std::string::npos) << line_of("coarse");
}
}  // namespace
