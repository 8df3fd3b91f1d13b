// The scenario's terrain.void_fill (options::VoidFillOptions): defaults,
// every key read, and mistakes named by their key.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/scenario.h"

namespace {

using namespace ig::io;

std::string with_terrain(const std::string& terrain) {
  return R"({"terrain": )" + terrain + R"(, "path": {"keys": [{"t": 0, "position": [0, 0, 100]}]}})";
}

TEST(ScenarioVoidFill, DefaultsAreGdalFillnodataWithMaxDistance400AndTwoSmoothingPasses) {
  const Scenario s = parse_scenario(with_terrain(R"({"file": "x.tif"})"));
  EXPECT_EQ(s.terrain.void_fill.max_distance, 400);
  EXPECT_EQ(s.terrain.void_fill.smoothing_iterations, 2);
}

TEST(ScenarioVoidFill, ReadsEveryKey) {
  const Scenario s =
      parse_scenario(with_terrain(R"({"file": "x.tif", "void_fill": {"max_distance": 64, "smoothing_iterations": 0}})"));
  EXPECT_EQ(s.terrain.void_fill.max_distance, 64);
  EXPECT_EQ(s.terrain.void_fill.smoothing_iterations, 0);
  const Scenario one = parse_scenario(with_terrain(R"({"file": "x.tif", "void_fill": {"smoothing_iterations": 32}})"));
  EXPECT_EQ(one.terrain.void_fill.max_distance, 400);
  EXPECT_EQ(one.terrain.void_fill.smoothing_iterations, 32);
}

TEST(ScenarioVoidFill, MistakesNameTheirKey) {
  struct Case {
    std::string terrain;
    std::vector<std::string> message_parts;
  };
  const std::vector<Case> cases = {
      {R"({"file": "x.tif", "void_fill": {"max_distance": 0}})", {"terrain.void_fill.max_distance", "1..1024"}},
      {R"({"file": "x.tif", "void_fill": {"max_distance": 1025}})", {"terrain.void_fill.max_distance", "1025"}},
      {R"({"file": "x.tif", "void_fill": {"max_distance": 12.5}})", {"terrain.void_fill.max_distance"}},
      {R"({"file": "x.tif", "void_fill": {"smoothing_iterations": -1}})",
       {"terrain.void_fill.smoothing_iterations", "0..32"}},
      {R"({"file": "x.tif", "void_fill": {"smoothing": 2}})", {"terrain.void_fill.smoothing", "unknown key"}},
      {R"({"file": "x.tif", "void_fill": 400})", {"terrain.void_fill"}},
      {R"({"generator": {}, "void_fill": {}})", {"terrain.void_fill", "only allowed with terrain.file"}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.terrain);
    try {
      parse_scenario(with_terrain(c.terrain));
      ADD_FAILURE() << "parsed";
    } catch (const ScenarioError& e) {
      for (const std::string& part : c.message_parts)
        EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what() << "\nshould name: " << part;
    }
  }
}

}  // namespace
