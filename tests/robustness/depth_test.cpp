// Depth precision: reversed-Z into a 32-bit float depth
// buffer, near 0.1 m, far 300 km. Two flat terrains 1 m apart, seen 10 km
// away, are drawn into the same frame (real renders, read back): the upper
// one must win at every pixel whichever is drawn first (no z-fighting). The
// two are told apart by colour (each scene has its own sun) and by depth.
// A conventional 24-bit depth buffer with the same near plane resolves only
// about d^2 * 2^-24 / near = 60 m at 10 km; reversed float Z about 1 mm.
#include <gtest/gtest.h>

#include <cstdio>

#include "gl/frame_state.h"
#include "robustness_support.h"

namespace {

using ig::render::Camera;

constexpr int kW = 160, kH = 120;

struct TwoSurfaces {
  long long upper_colour = 0, lower_colour = 0, sky = 0;
  double worst_depth_error_m = 0.0;  // of the upper surface's expected view distance
};

// Renders `first` (with sky) and then `second` into the same target, reads back.
TwoSurfaces render_pair(double separation_m, bool lower_first, const Camera& camera) {
  robustness::ensure_gl();
  ig::render::ShadingParams overhead, grazing;
  overhead.sun_direction = {0.0f, 0.0f, 1.0f};  // flat ground fully lit: bright
  grazing.sun_direction = {1.0f, 0.0f, 0.02f};  // flat ground barely lit: dark
  overhead.fog_visibility_m = grazing.fog_visibility_m = 0.0;
  // The second surface is drawn outside a FrameRenderer, so it is shaded where it is drawn.
  overhead.deferred_shading = grazing.deferred_shading = false;
  const auto lower_hf = robustness::flat_terrain(129, 100.0, 0.0f);
  const auto upper_hf = robustness::flat_terrain(129, 100.0, float(separation_m));
  robustness::Rig rig(lower_first ? lower_hf : upper_hf, "reference", kW, kH, lower_first ? grazing : overhead);
  ig::render::TerrainScene second_scene(lower_first ? upper_hf : lower_hf, lower_first ? overhead : grazing);
  auto second =
      ig::render::make_method("reference", second_scene, robustness::shader_dir(), ig::render::TwoLevelOptions{});

  rig.render(camera);  // clears, draws the first surface and the sky
  // The second surface into the same colour and depth, with the frame's depth test.
  rig.target().bind();
  ig::gl::use_frame_depth_test();
  const Camera local = second_scene.local_camera(camera);
  second->update(local);
  second->draw(local, rig.target());
  ig::gl::finish();
  const auto depth = rig.target().read_depth();
  const auto rgba = rig.target().read_rgba();

  // The upper surface is lit from overhead (sum of RGB ~297), the lower one
  // by a grazing sun (~71). Expected depth: the upper plane's, per pixel.
  TwoSurfaces r;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const size_t p = size_t(y) * kW + x;
      if (depth[p] == 0.0f) {
        ++r.sky;
        continue;
      }
      const int lum = rgba[4 * p] + rgba[4 * p + 1] + rgba[4 * p + 2];
      if (lum > 180)
        ++r.upper_colour;
      else
        ++r.lower_colour;
      const glm::dvec3 ray = camera.pixel_ray(x, y, kW, kH);
      const double t = (separation_m - camera.position.z) / ray.z;  // to the upper plane
      const double axial = t * glm::dot(ray, camera.forward());
      r.worst_depth_error_m =
          std::max(r.worst_depth_error_m, std::abs(camera.depth_to_view_distance(depth[p]) - axial));
    }
  return r;
}

Camera far_camera(double pitch_deg) {
  // 10 km from the surfaces along the centre ray, over the middle of the 12.8 km DEM.
  const double d = 10000.0, pitch = glm::radians(pitch_deg);
  const glm::dvec3 target(6400.0, 6400.0, 0.0);
  const glm::dvec3 eye = target + glm::dvec3(0.0, -d * std::cos(pitch), d * std::sin(-pitch));
  Camera c = robustness::camera_at(eye, 0.0, pitch_deg, 0.0, 20.0, kW, kH);
  c.near_m = 0.1;
  c.far_m = 300000.0;
  return c;
}

TEST(DepthPrecision, FrameUsesReversedZIntoAFloatDepthBuffer) {
  const auto hf = robustness::flat_terrain(17, 10.0, 0.0f);
  robustness::Rig rig(hf, "reference", kW, kH);
  rig.render(robustness::camera_at({80, 80, 50}, 0, -45));
  EXPECT_TRUE(ig::gl::is_float_depth(rig.target().depth_texture()));
  EXPECT_TRUE(ig::gl::clip_depth_zero_to_one());
  // Reversed: the near plane maps to 1, the far plane to 0, and 10 km vs
  // 10 km - 1 m differ by many float steps.
  Camera c = far_camera(-90);
  auto depth_of = [&](double d) {
    const glm::vec4 p = c.projection() * glm::vec4(0, 0, float(-d), 1);
    return p.z / p.w;
  };
  EXPECT_NEAR(depth_of(c.near_m), 1.0, 1e-6);
  EXPECT_NEAR(depth_of(c.far_m), 0.0, 1e-9);
  const float a = depth_of(10000.0), b = depth_of(9999.0);
  const double ulps = (double(b) - double(a)) / (std::nextafter(a, 1.0f) - a);
  std::printf(
      "[depth] near 0.1 m, far 300 km: depth(10 km) = %.6e, depth(10 km - 1 m) = %.6e, %.0f float steps apart\n", a, b,
      ulps);
  EXPECT_GT(ulps, 100.0);
}

TEST(DepthPrecision, SurfacesOneMetreApartAtTenKilometresDoNotFight) {
  for (double pitch : {-90.0, -30.0}) {
    const Camera cam = far_camera(pitch);
    for (bool lower_first : {true, false}) {
      const TwoSurfaces r = render_pair(1.0, lower_first, cam);
      std::printf(
          "[depth] pitch %+.0f, %s first: upper wins %lld, lower shows %lld, sky %lld; worst depth error "
          "%.3f m\n",
          pitch, lower_first ? "lower" : "upper", r.upper_colour, r.lower_colour, r.sky, r.worst_depth_error_m);
      EXPECT_EQ(r.sky, 0);
      EXPECT_EQ(r.lower_colour, 0) << "the lower surface shows through (z-fighting)";
      EXPECT_EQ(r.upper_colour, kW * kH);
      // The depth read back is the upper plane's, well inside the 1 m separation.
      EXPECT_LT(r.worst_depth_error_m, 0.1);
    }
  }
}

TEST(DepthPrecision, SmallestSeparationResolvedAtTenKilometres) {
  // Reported, not asserted beyond 1 m: how far below 1 m the separation can go
  // looking straight down from 10 km before the lower surface shows through.
  const Camera cam = far_camera(-90);
  double smallest_clean = 0.0;
  for (double sep : {1.0, 0.1, 0.01, 0.003, 0.001, 0.0003}) {
    const TwoSurfaces a = render_pair(sep, true, cam), b = render_pair(sep, false, cam);
    const bool clean = a.lower_colour == 0 && b.lower_colour == 0;
    std::printf("[depth] separation %.4f m at 10 km: lower surface shows in %lld / %lld pixels\n", sep, a.lower_colour,
                b.lower_colour);
    if (!clean) break;
    smallest_clean = sep;
  }
  std::printf("[depth] smallest separation without fighting at 10 km: %.4f m\n", smallest_clean);
  RecordProperty("smallest_clean_separation_m", std::to_string(smallest_clean));
  EXPECT_GT(smallest_clean, 0.0) << "even 1 m is not resolved";
}

}  // namespace
