// Two scenario runners alive on one thread, each with its own GL context:
// each draws into its own, whichever was made last, and destroying one
// leaves the other's objects alone.
#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "io/scenario.h"
#include "session/scenario_runner.h"

namespace {
using ig::session::RunOptions;
using ig::session::ScenarioRunner;

RunOptions options(const std::string& method) {
  RunOptions o;
  o.width = 160;
  o.height = 120;
  o.headless = true;
  o.shader_dir = std::string(IG_BIN_DIR) + "/shaders";
  o.method = method;
  return o;
}

ig::io::Scenario scenario() { return ig::io::load_scenario(std::string(IG_SOURCE_DIR) + "/scenarios/default.json"); }

// Frames 0..frames-1 of `method` with no other runner about: the picture of the last.
std::vector<std::uint8_t> alone(const std::string& method, int frames) {
  ScenarioRunner runner(scenario(), options(method));
  for (int k = 0; k < frames; ++k) runner.render_frame(k);
  return runner.channels().front().target->read_rgba();
}

TEST(TwoRunners, EachDrawsInItsOwnContext) {
  const auto cdlod_alone = alone("cdlod", 3), twolevel_alone = alone("twolevel", 3);
  ASSERT_NE(cdlod_alone, twolevel_alone);
  // Made in this order, the two-level runner's context is current when the
  // CDLOD runner renders first; their GL objects have different names.
  ScenarioRunner cdlod(scenario(), options("cdlod"));
  auto twolevel = std::make_unique<ScenarioRunner>(scenario(), options("twolevel"));
  for (int k = 0; k < 3; ++k) {
    cdlod.render_frame(k);
    const auto cdlod_now = cdlod.channels().front().target->read_rgba();
    twolevel->render_frame(k);
    if (k == 2) {
      EXPECT_EQ(cdlod_now, cdlod_alone);
      EXPECT_EQ(twolevel->channels().front().target->read_rgba(), twolevel_alone);
    }
  }
  // Destroying the two-level runner deletes its objects, not CDLOD's.
  twolevel.reset();
  for (int k = 0; k < 3; ++k) cdlod.render_frame(k);
  EXPECT_EQ(cdlod.channels().front().target->read_rgba(), cdlod_alone);
}

}  // namespace
