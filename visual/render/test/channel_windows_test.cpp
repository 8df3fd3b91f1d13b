// Every channel keeps its own full-resolution windows (issue 16): two
// two-level methods on one scene beyond its texture limit, looking at
// different places, each keep a height window on their own Level1, so
// rendering them in turn uploads nothing once both are placed (one shared
// window would be moved across the DEM twice a frame), and each channel's
// picture is the one it gets alone.

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <stdexcept>

#include "render/test/lod_view_checks.h"

namespace {

TEST(ChannelWindows, EachChannelKeepsItsOwnWindowOnItsLevel1) {
  lod_views::World world(1025);
  // Texture limit 513: an overview every 2nd sample, full resolution only in the windows.
  ig::render::TerrainScene scene(world.hf, ig::render::ShadingParams{}, std::nullopt, 513);
  scene.enable_height_window(256);
  ASSERT_GT(scene.overview_step(), 1);
  const double s = world.hf.spacing_x_m;
  const auto view_a = lod_views::camera_at(world.hf, 200 * s, 200 * s, 300.0, 45.0, -50.0);
  const auto view_b = lod_views::camera_at(world.hf, 820 * s, 800 * s, 300.0, 225.0, -50.0);

  ig::render::TwoLevelMethod alone(scene, world.shader_dir);
  lod_views::render(world, alone, view_b, &scene);
  const auto b_alone_again = lod_views::render(world, alone, view_b, &scene);  // size settled as below

  ig::render::TwoLevelMethod a(scene, world.shader_dir);
  EXPECT_EQ(scene.window_sets(), 2);
  auto uploaded = [&] {
    long long n = 0;
    for (int set = 0; set < scene.window_sets(); ++set) n += scene.height_window(set)->uploaded_samples();
    return n;
  };
  long long after_first_round = 0;
  lod_views::Frame last_b;
  for (int round = 0; round < 3; ++round) {
    lod_views::render(world, a, view_a, &scene);
    last_b = lod_views::render(world, alone, view_b, &scene);
    if (round == 0) after_first_round = uploaded();
  }
  EXPECT_GT(after_first_round, 0);
  EXPECT_EQ(uploaded(), after_first_round) << "a window moved although no view did";
  const glm::ivec2 wa = scene.height_window(1)->origin(), wb = scene.height_window(0)->origin();
  EXPECT_GT(std::abs(wa.x - wb.x) + std::abs(wa.y - wb.y), 400) << "the windows are not on their own views";
  EXPECT_EQ(last_b.rgba, b_alone_again.rgba) << "channel b's picture changed when a second channel was added";

  // A set given back is reused, not duplicated.
  { ig::render::TwoLevelMethod gone(scene, world.shader_dir); }
  EXPECT_EQ(scene.window_sets(), 3);
  ig::render::TwoLevelMethod again(scene, world.shader_dir);
  EXPECT_EQ(scene.window_sets(), 3);
}

// Programs link the window's reads only if the scene has a window when they
// are made; a window enabled after a program linked without them would be
// drawn past, so it is refused instead.
TEST(ChannelWindows, AWindowAfterAProgramLinkedWithoutItIsRefused) {
  lod_views::World world(257);
  ig::render::TerrainScene before(world.hf, ig::render::ShadingParams{});
  before.enable_height_window(256);
  const auto windowed = before.shading_stages({"terrain.frag"});
  EXPECT_NE(std::find(windowed.begin(), windowed.end(), "height_at_window.frag"), windowed.end());

  ig::render::TerrainScene after(world.hf, ig::render::ShadingParams{});
  const auto whole = after.shading_stages({"terrain.frag"});
  EXPECT_NE(std::find(whole.begin(), whole.end(), "height_at_whole.frag"), whole.end());
  EXPECT_THROW(after.enable_height_window(256), std::logic_error);
  EXPECT_NO_THROW(after.enable_height_window(0)) << "no window: nothing linked is missing";
}

}  // namespace
