// frames.csv: columns fixed by the first row, each name once. No GL.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "stats/frame_log.h"

namespace {

using ig::stats::Cell;
using ig::stats::FrameLog;

std::string temp_csv(const char* name) { return testing::TempDir() + name; }

std::string read_all(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(FrameLog, WritesTheHeaderOnceAndTheFrameTimes) {
  const std::string path = temp_csv("frame_log_rows.csv");
  {
    FrameLog log(path);
    log.add_row({Cell("frame", 0), Cell("wall_ms", 12.5), Cell("passes", std::string("terrain+sky"))});
    log.add_row({Cell("frame", 1), Cell("wall_ms", 10.0), Cell("passes", std::string("sky"))});
    ASSERT_EQ(log.frame_ms().size(), 2u);
    EXPECT_DOUBLE_EQ(log.frame_ms()[0], 12.5);
    EXPECT_DOUBLE_EQ(log.frame_ms()[1], 10.0);
  }
  EXPECT_EQ(read_all(path), "frame,wall_ms,passes\n0,12.5,terrain+sky\n1,10,sky\n");
  std::remove(path.c_str());
}

TEST(FrameLog, RejectsRowsThatChangeTheColumns) {
  const std::string path = temp_csv("frame_log_columns.csv");
  FrameLog log(path);
  log.add_row({Cell("frame", 0), Cell("wall_ms", 1.0)});
  EXPECT_THROW(log.add_row({Cell("frame", 1)}), std::logic_error);
  EXPECT_THROW(log.add_row({Cell("wall_ms", 1.0), Cell("frame", 1)}), std::logic_error);
  std::remove(path.c_str());
}

// A stage time and a pass of the same name (sky_ms, the sky pass's
// sky_pass_ms) must not both become one column name.
TEST(FrameLog, RejectsAColumnNamedTwice) {
  const std::string path = temp_csv("frame_log_twice.csv");
  FrameLog log(path);
  try {
    log.add_row({Cell("frame", 0), Cell("sky_ms", 1.0), Cell("sky_ms", 0.5)});
    FAIL() << "no error for a column named twice";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("sky_ms twice"), std::string::npos) << e.what();
  }
  std::remove(path.c_str());
}

}  // namespace
