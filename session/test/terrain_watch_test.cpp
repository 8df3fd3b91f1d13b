// Frames that show no terrain or look from under it (session/terrain_watch.h),
// judged on a real heightfield, its min/max pyramid and the cameras the
// renderer would use (no GL needed).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/pose.h"
#include "session/terrain_watch.h"
#include "terrain/georef.h"
#include "terrain/height_pyramid.h"

namespace {

using namespace ig;

// 257 x 257 samples 30 m apart (7680 m a side): a hill rising to 400 m in
// the middle, 0 m at the edges.
terrain::Heightfield hill() {
  terrain::Heightfield hf;
  hf.width = hf.height = 257;
  hf.spacing_x_m = hf.spacing_y_m = 30.0;
  hf.heights.resize(257 * 257);
  for (int j = 0; j < 257; ++j)
    for (int i = 0; i < 257; ++i) {
      const double dx = (i - 128) / 128.0, dy = (j - 128) / 128.0;
      hf.ref(i, j) = float(400.0 * std::max(0.0, 1.0 - dx * dx - dy * dy));
    }
  hf.finalize_stats();
  return hf;
}

render::Camera camera(const glm::dvec3& eye, double heading, double pitch) {
  render::Camera c;
  c.position = eye;
  c.attitude = io::attitude_from_hpr(io::Hpr{heading, pitch, 0.0});
  c.fov_y_deg = 60.0;
  c.aspect = 4.0 / 3.0;
  return c;
}

TEST(TerrainWatch, DistanceOutsideTheExtent) {
  const auto hf = hill();
  EXPECT_EQ(session::distance_outside_terrain(hf, {100.0, 7000.0}), 0.0);
  EXPECT_DOUBLE_EQ(session::distance_outside_terrain(hf, {-500.0, 100.0}), 500.0);
  EXPECT_DOUBLE_EQ(session::distance_outside_terrain(hf, {7680.0 + 300.0, 7680.0 + 400.0}), 500.0);
}

TEST(TerrainWatch, TerrainInViewFollowsTheFrustum) {
  const auto hf = hill();
  const terrain::HeightPyramid pyramid(hf);
  const glm::dvec3 eye(3840.0, 1000.0, 600.0);
  EXPECT_TRUE(session::terrain_in_view(hf, pyramid, camera(eye, 0.0, -10.0)));   // towards the hill
  EXPECT_TRUE(session::terrain_in_view(hf, pyramid, camera(eye, 180.0, -10.0))); // the last 1000 m of it
  EXPECT_FALSE(session::terrain_in_view(hf, pyramid, camera(eye, 0.0, 60.0)));   // sky: 30..90 deg up
  // From 20 km south, looking south: the terrain is behind.
  const glm::dvec3 far_eye(3840.0, -20000.0, 600.0);
  EXPECT_FALSE(session::terrain_in_view(hf, pyramid, camera(far_eye, 180.0, 0.0)));
  EXPECT_TRUE(session::terrain_in_view(hf, pyramid, camera(far_eye, 0.0, 0.0)));
}

TEST(TerrainWatch, DepthBelowTheSurface) {
  const auto hf = hill();
  const auto under = session::depth_below_terrain(hf, {3840.0, 3840.0, 350.0});
  ASSERT_TRUE(under.has_value());
  EXPECT_NEAR(*under, 50.0, 1e-3);  // the top of the hill is 400 m
  EXPECT_LT(*session::depth_below_terrain(hf, {3840.0, 3840.0, 450.0}), 0.0);
  EXPECT_FALSE(session::depth_below_terrain(hf, {-10.0, 3840.0, -100.0}).has_value());  // not over the terrain
}

TEST(TerrainWatch, CountsAndWarnsOnceEach) {
  auto hf = hill();
  hf.georef = terrain::make_geographic_georef(46.5, 7.9, 30.0, 30.0);
  const terrain::HeightPyramid pyramid(hf);
  std::vector<std::string> lines;
  session::TerrainWatch watch("ig run", [&](const std::string& l) { lines.push_back(l); });
  auto frame = [&](int k, const glm::dvec3& eye, double heading, double pitch) {
    watch.observe(hf, pyramid, k, k * 0.5, eye, {camera(eye, heading, pitch)});
  };
  frame(0, {3840.0, 1000.0, 600.0}, 0.0, -10.0);  // a normal view
  EXPECT_EQ(watch.frames_outside(), 0u);
  EXPECT_TRUE(lines.empty());
  frame(1, {-650000.0, 3000.0, 1200.0}, 90.0, -5.0);  // a wrong longitude: 650 km west
  frame(2, {-650000.0, 3000.0, 1200.0}, 90.0, -5.0);
  EXPECT_EQ(watch.frames_outside(), 2u);
  ASSERT_EQ(lines.size(), 1u);
  for (const char* want : {"ig run: warning: frame 1 (t 0.500 s)", "x -650000 m", "lat 46.", "lon ", "650 km outside",
                           "frames_outside_terrain"})
    EXPECT_NE(lines[0].find(want), std::string::npos) << lines[0] << "\nwanted: " << want;
  frame(3, {3840.0, 1000.0, 600.0}, 0.0, 60.0);  // over the terrain, looking at the sky: counted, not warned again
  EXPECT_EQ(watch.frames_outside(), 3u);
  EXPECT_EQ(lines.size(), 1u);
  frame(4, {3840.0, 3840.0, 350.0}, 0.0, 0.0);  // inside the hill
  frame(5, {3840.0, 3840.0, 340.0}, 0.0, 0.0);
  EXPECT_EQ(watch.frames_below(), 2u);
  ASSERT_EQ(lines.size(), 2u);
  for (const char* want : {"frame 4 (t 2.000 s)", "50.0 m below the terrain surface", "frames_below_terrain"})
    EXPECT_NE(lines[1].find(want), std::string::npos) << lines[1] << "\nwanted: " << want;
}

}  // namespace
