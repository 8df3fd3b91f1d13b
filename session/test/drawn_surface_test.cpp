// "As drawn" HAT/HOT (ig serve --host-surface drawn): after a two-level
// frame, heights inside Level1 are the full-resolution surface's and outside
// it Level0's; HostServices answers from them.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "session/drawn_surface.h"
#include "session/host_services.h"
#include "session/scenario_runner.h"
#include "session/scene_setup.h"
#include "io/scenario.h"
#include "render/twolevel_method.h"

namespace {

using ig::session::DrawnSurface;
using ig::session::RunOptions;
using ig::session::ScenarioRunner;

TEST(DrawnSurface, Level1IsFullResolutionAndLevel0IsTheMesh) {
  RunOptions o;
  o.width = 160;
  o.height = 120;
  o.method = "twolevel";
  o.headless = true;
  o.frames = 1;
  o.shader_dir = std::string(IG_BIN_DIR) + "/shaders";
  ScenarioRunner runner(ig::io::load_scenario(std::string(IG_SOURCE_DIR) + "/scenarios/default.json"), o);
  const ig::session::FrameResult f = runner.render_frame(0);
  auto* method = dynamic_cast<ig::render::TwoLevelMethod*>(&runner.method());
  ASSERT_NE(method, nullptr);
  const auto& hf = runner.heightfield();
  DrawnSurface drawn(runner);
  const glm::ivec2 origin = method->level1_origin();
  const int n = method->level1_size();
  ASSERT_LT(n, hf.width);  // some terrain is Level0
  // Inside Level1: full resolution (no drawn height of its own).
  const double cx = (origin.x + n / 2) * hf.spacing_x_m, cy = (origin.y + n / 2) * hf.spacing_y_m;
  EXPECT_FALSE(drawn.level0_height_at(cx, cy));
  // Outside: Level0. At its vertices it is the DEM sample; between them it
  // differs from the full-resolution surface.
  int vertices = 0;
  double largest_gap = 0.0;
  for (const glm::ivec2 s : method->level0().samples) {
    const bool in_level1 = s.x >= origin.x && s.y >= origin.y && s.x <= origin.x + n - 1 && s.y <= origin.y + n - 1;
    if (in_level1) continue;
    const auto h = drawn.level0_height_at(s.x * hf.spacing_x_m, s.y * hf.spacing_y_m);
    ASSERT_TRUE(h);
    EXPECT_NEAR(*h, hf.at(s.x, s.y), 1e-3);
    ++vertices;
  }
  EXPECT_GT(vertices, 100);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> ux(0, hf.extent_x_m()), uy(0, hf.extent_y_m());
  for (int k = 0; k < 2000; ++k) {
    const double x = ux(rng), y = uy(rng);
    if (const auto h = drawn.level0_height_at(x, y)) largest_gap = std::max(largest_gap, std::abs(*h - hf.sample_surface(x, y)));
  }
  EXPECT_GT(largest_gap, 1.0);

  // HostServices answers HOT from the drawn surface when asked to.
  ig::session::HostServices services(hf, runner.scene().earth_radius_m(), ig::session::geodetic_placer(hf),
                                 ig::session::local_to_geodetic(hf), {}, &runner.scene().height_pyramid());
  services.set_drawn_height([&drawn](double x, double y) { return drawn.level0_height_at(x, y); });
  const auto to_geo = ig::session::local_to_geodetic(hf);
  ASSERT_TRUE(to_geo);
  ig::io::wire::HatHotRequest inside, outside;
  inside.type = outside.type = ig::io::wire::HatHotType::Hot;
  inside.point = *to_geo(glm::dvec3(cx, cy, 0));
  const glm::ivec2 far_sample = origin.x > hf.width / 2 ? glm::ivec2(5, 5) : glm::ivec2(hf.width - 6, hf.height - 6);
  const double fx = far_sample.x * hf.spacing_x_m + 7.3, fy = far_sample.y * hf.spacing_y_m + 3.1;
  outside.point = *to_geo(glm::dvec3(fx, fy, 0));
  const auto a = std::get<ig::io::wire::HatHotResponse>(services.answer(inside, f.pose));
  const auto b = std::get<ig::io::wire::HatHotResponse>(services.answer(outside, f.pose));
  ASSERT_TRUE(a.valid && b.valid);
  EXPECT_NEAR(a.hot_m, hf.sample_surface(cx, cy), 1e-6);
  ASSERT_TRUE(drawn.level0_height_at(fx, fy));
  EXPECT_NEAR(b.hot_m, *drawn.level0_height_at(fx, fy), 1e-6);
}

}  // namespace
