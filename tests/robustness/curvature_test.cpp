// Earth curvature (issue 8, item 5): the drop below the eye's tangent plane,
// d^2 / (R + sqrt(R^2 - d^2)), applied per vertex in every terrain vertex
// shader (u_earth_radius_m, set by TerrainScene::bind_common) and on the CPU
// where it must agree with the image: frustum culling (Frustum::intersects_box)
// and the look-at ray cast (lod/look_at_point.h). Checked against the exact
// sphere: the CPU formula, the rendered depth of a flat DEM (its drawn
// surface is then exactly a sphere of radius R touching the ground under the
// eye) and the horizon it shows; the scenario option and its default.
#include <gtest/gtest.h>

#include <cstdio>

#include "session/scene_setup.h"
#include "io/scenario.h"
#include "lod/look_at_point.h"
#include "robustness_support.h"
#include "terrain/earth_curvature.h"
#include "terrain/georef.h"

namespace {

using ig::render::Camera;
using ig::terrain::curvature_drop;
using ig::terrain::kEarthRadiusM;
using robustness::Frame;
using robustness::Rig;

TEST(EarthCurvature, CpuDropMatchesTheExactSphere) {
  // Reference: R - sqrt(R^2 - d^2) in long double from 1 km (below that its
  // own cancellation dominates), the series d^2/2R + d^4/8R^3 + d^6/16R^5 below.
  const long double R = kEarthRadiusM;
  double worst_rel = 0.0;
  for (double d = 1.0; d <= 2e6; d *= 1.1) {
    const long double d2 = (long double)d * d;
    const long double exact = d >= 1000.0
                                  ? R - std::sqrt(R * R - d2)
                                  : d2 / (2 * R) + d2 * d2 / (8 * R * R * R) + d2 * d2 * d2 / (16 * R * R * R * R * R);
    const double got = curvature_drop(d, kEarthRadiusM);
    worst_rel = std::max(worst_rel, double(std::abs(got - exact) / exact));
  }
  // The GPU's float evaluation of the same formula (emulated here).
  double worst_float_m = 0.0;
  for (double d = 100.0; d <= 400000.0; d += 997.0) {
    const float r = float(kEarthRadiusM), d2 = float(d) * float(d);
    const float gpu = d2 / (r + std::sqrt(r * r - d2));
    worst_float_m = std::max(worst_float_m, std::abs(double(gpu) - curvature_drop(d, kEarthRadiusM)));
  }
  std::printf(
      "[curvature] drop at 1 / 10 / 100 / 300 km: %.4f / %.3f / %.1f / %.1f m; d^2/2R differs by %.1e / %.1e / "
      "%.3f / %.2f m\n",
      curvature_drop(1e3, kEarthRadiusM), curvature_drop(1e4, kEarthRadiusM), curvature_drop(1e5, kEarthRadiusM),
      curvature_drop(3e5, kEarthRadiusM), curvature_drop(1e3, kEarthRadiusM) - 1e6 / (2 * kEarthRadiusM),
      curvature_drop(1e4, kEarthRadiusM) - 1e8 / (2 * kEarthRadiusM),
      curvature_drop(1e5, kEarthRadiusM) - 1e10 / (2 * kEarthRadiusM),
      curvature_drop(3e5, kEarthRadiusM) - 9e10 / (2 * kEarthRadiusM));
  std::printf(
      "[curvature] CPU vs R - sqrt(R^2 - d^2) (long double), 1 m .. 2000 km: worst relative %.1e; float (GPU) "
      "formula within 400 km: worst %.4f m\n",
      worst_rel, worst_float_m);
  EXPECT_LT(worst_rel, 1e-10);
  EXPECT_LT(worst_float_m, 0.02);  // float rounding: ~1e-7 of a drop up to 12.6 km
  EXPECT_EQ(curvature_drop(1e4, 0.0), 0.0);
  EXPECT_EQ(curvature_drop(1e9, kEarthRadiusM), kEarthRadiusM);  // clamped at the sphere's widest point
}

TEST(EarthCurvature, FrustumCullingKeepsBoxesTheDropBringsIntoView) {
  // Level view, 2 degrees tall: a box 100 km ahead at 2000-2100 m lies above
  // the top plane on flat ground, but the drop there (785 m) brings it in.
  Camera c = robustness::camera_at({0, 0, 0}, 0, 0, 0, 2.0);
  const glm::dvec3 lo(-500, 99500, 2000), hi(500, 100500, 2100);
  EXPECT_FALSE(ig::render::frustum_of(c).intersects_box(lo, hi));
  c.earth_radius_m = kEarthRadiusM;
  EXPECT_TRUE(ig::render::frustum_of(c).intersects_box(lo, hi));
  // And one that stays below the view either way is still culled.
  EXPECT_FALSE(ig::render::frustum_of(c).intersects_box({-500, 99500, -5000}, {500, 100500, -4000}));
}

// ------------------------------------------------- the rendered sphere --

constexpr int kW = 161, kH = 121;  // odd: pixel (80, 60) looks exactly along the axis

// 513 x 513 flat samples at 250 m: 128 km, height 0.
ig::terrain::Heightfield big_flat() { return robustness::flat_terrain(513, 250.0, 0.0f); }

// Eye 1000 m over the DEM's south-centre, looking north 0.8 degrees down,
// 8 degrees tall: the geometric horizon (113 km, 1.02 degrees down) is in view.
Camera sphere_camera() { return robustness::camera_at({64000.0, 2000.0, 1000.0}, 0.0, -0.8, 0.0, 8.0, kW, kH); }

// Distance along the view axis to the sphere of radius R touching z = 0 under the eye, or -1.
double sphere_axial(const Camera& c, int x, int y) {
  const glm::dvec3 u = c.pixel_ray(x, y, kW, kH);
  const glm::dvec3 centre(c.position.x, c.position.y, -kEarthRadiusM);
  const glm::dvec3 oc = c.position - centre;
  const double b = glm::dot(oc, u), cc = glm::dot(oc, oc) - kEarthRadiusM * kEarthRadiusM;
  const double disc = b * b - cc;
  if (disc < 0) return -1.0;
  const double t = -b - std::sqrt(disc);
  return t > 0 ? t * glm::dot(u, c.forward()) : -1.0;
}

int first_terrain_row(const Frame& f, int x) {
  for (int y = 0; y < f.h; ++y)
    if (f.terrain(x, y)) return y;
  return f.h;
}

TEST(EarthCurvature, FlatDemDrawsTheSphereInEveryMethod) {
  // Every registered method in turn (one process per test keeps the label quick).
  for (const std::string& method : ig::render::method_names()) {
    SCOPED_TRACE(method);
    const Camera cam = sphere_camera();
    Frame flat_world;
    {
      Rig rig(big_flat(), method, kW, kH);
      flat_world = rig.render(cam, 4);
    }
    Rig rig(big_flat(), method, kW, kH, {}, {}, kEarthRadiusM);
    const Frame f = rig.render(cam, 4);
    EXPECT_EQ(robustness::finite_problems(f), "");

    // Depth of every terrain pixel against the sphere, and sky where the ray misses it.
    long long checked = 0, wrong_kind = 0;
    std::vector<double> rel;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        const double s = sphere_axial(cam, x, y);
        const bool near_limb =
            y > 0 && y < kH - 1 && (sphere_axial(cam, x, y - 1) < 0) != (sphere_axial(cam, x, y + 1) < 0);
        if (near_limb) continue;
        ++checked;
        if ((s > 0) != f.terrain(x, y)) ++wrong_kind;
        if (s > 0 && f.terrain(x, y)) rel.push_back(std::abs(f.view_distance(x, y) - s) / s);
      }
    std::sort(rel.begin(), rel.end());
    const double p95 = rel.empty() ? 0.0 : rel[size_t(0.95 * (rel.size() - 1))], worst = rel.empty() ? 0.0 : rel.back();
    // The horizon row per column: curved vs flat vs the sphere.
    double horizon_err = 0.0, lowered = 0.0;
    for (int x = 0; x < kW; ++x) {
      int expect = kH;
      for (int y = 0; y < kH; ++y)
        if (sphere_axial(cam, x, y) > 0) {
          expect = y;
          break;
        }
      horizon_err = std::max(horizon_err, double(std::abs(first_terrain_row(f, x) - expect)));
      lowered += double(first_terrain_row(f, x) - first_terrain_row(flat_world, x)) / kW;
    }
    std::printf(
        "[curvature] %-10s flat DEM vs sphere: %lld pixels, %lld terrain/sky wrong; |dD|/D p95 %.2e max %.2e; "
        "horizon row off by at most %.0f px; %.1f px lower than the flat world\n",
        method.c_str(), checked, wrong_kind, p95, worst, horizon_err, lowered);
    if (auto* tl = robustness::as_twolevel(rig.method()))
      std::printf(
          "[curvature] twolevel on the flat DEM: Level0 %d triangles (refined by the curvature sag alone), "
          "Level1 N=%d\n",
          tl->level0().triangle_count, tl->level1_size());
    EXPECT_GT(lowered, 4.0) << "the drop is not applied by this method's vertex shader";
    if (method == "reference") {
      // Every sample a vertex (250 m): chords sit 250^2 / 8R = 1.2 mm above the sphere.
      EXPECT_LE(wrong_kind, kW) << "pixels on the wrong side of the limb";
      EXPECT_LT(p95, 1e-4);
      EXPECT_LT(worst, 1e-3);
      EXPECT_LE(horizon_err, 1.0);
    }
    if (method == "twolevel" || method == "roam") {
      // ROAM meshes (Level0, the roam baseline) count each triangle's
      // curvature sag L^2/8R in its error, so on a flat DEM they still refine.
      // Measured p95: twolevel 6.5e-4, roam 0.030 (its 2 px tolerance seen
      // at grazing angles); 0.73 / 0.90 without the sag.
      EXPECT_LE(wrong_kind, kW);
      EXPECT_LT(p95, method == "roam" ? 0.06 : 0.01);
    }
  }
}

TEST(EarthCurvature, TwoLevelCentreFollowsTheCurvedSurface) {
  // Looking 5 degrees down from 1.2 km over 31 km of hills: the centre ray
  // meets the curved surface ~11 km out, where the drop is ~10 m. E must be
  // that point (the centre pixel's depth), not the flat-world hit.
  auto hf = robustness::hills(513, 60.0, 600.0);
  const glm::dvec3 eye(3000, 3000, hf.max_m + 1200.0);
  const Camera cam = robustness::camera_at(eye, 45, -5, 0, 30, kW, kH);
  Rig rig(hf, "twolevel", kW, kH);
  rig.scene().set_earth_radius(kEarthRadiusM);
  const Frame f = rig.render(cam, 4);
  const auto& e = robustness::as_twolevel(rig.method())->look_at();
  ASSERT_TRUE(e.hit);
  const double d = glm::length(glm::dvec2(e.point - eye));
  const glm::dvec3 drawn = e.point - glm::dvec3(0, 0, curvature_drop(d, kEarthRadiusM));
  const double e_axial = glm::dot(drawn - eye, cam.forward());
  const double pixel = f.view_distance(kW / 2, kH / 2);
  const ig::terrain::HeightPyramid pyr(rig.heightfield());
  const auto flat_e = ig::lod::find_look_at_point(rig.heightfield(), pyr, eye, cam.forward(), cam.up(), 0.0);
  std::printf(
      "[curvature] twolevel E at %.0f m (drop %.1f m): axial %.2f m, centre pixel %.2f m; the flat-world E is "
      "%.0f m away from it\n",
      d, curvature_drop(d, kEarthRadiusM), e_axial, pixel, glm::length(glm::dvec2(flat_e.point - e.point)));
  EXPECT_NEAR(e_axial, pixel, 1e-3 * pixel);
  EXPECT_GT(glm::length(glm::dvec2(flat_e.point - e.point)), 20.0) << "the test would not tell curved from flat";
}

TEST(EarthCurvature, TwoLevelErrorAgainstTheReferenceStaysWithCurvature) {
  // Hills 31 km across, 300 m above ground, 2 degrees down: the two-level
  // image against the reference, both flat and both curved.
  const auto hf = robustness::hills(513, 60.0, 900.0);
  const glm::dvec3 eye(2500, 2500, hf.sample_surface(2500, 2500) + 300.0);
  const Camera cam = robustness::camera_at(eye, 40, -2, 0, 45, kW, kH);
  for (double radius : {0.0, kEarthRadiusM}) {
    Frame ref, tl;
    {
      Rig rig(hf, "reference", kW, kH);
      rig.scene().set_earth_radius(radius);
      ref = rig.render(cam);
    }
    {
      ig::render::TwoLevelOptions small;
      small.max_level1 = 129;  // so Level0 draws most of the view
      Rig rig(hf, "twolevel", kW, kH, {}, small);
      rig.scene().set_earth_radius(radius);
      tl = rig.render(cam, 10);
    }
    long long terrain = 0, holes = 0;
    std::vector<double> rel;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        if (!ref.terrain(x, y)) continue;
        ++terrain;
        if (!tl.terrain(x, y))
          ++holes;
        else
          rel.push_back(std::abs(tl.view_distance(x, y) / ref.view_distance(x, y) - 1.0));
      }
    std::sort(rel.begin(), rel.end());
    const double p95 = rel.empty() ? 0.0 : rel[size_t(0.95 * (rel.size() - 1))];
    std::printf("[curvature] twolevel vs reference, %s: terrain %lld px, holes %lld, |dD|/D p95 %.4f\n",
                radius > 0 ? "curved" : "flat  ", terrain, holes, p95);
    EXPECT_EQ(robustness::finite_problems(tl), "");
    EXPECT_LE(holes, terrain / 100);
    EXPECT_LT(p95, 0.1);
  }
}

// ------------------------------------------------------ scenario option --

TEST(EarthCurvature, ScenarioOptionAndDefault) {
  const std::string base = R"({"terrain": {"generator": {}}, "path": {"keys": [{"t": 0, "position": [0, 0, 100]}]}})";
  auto with = [&](const std::string& render) {
    return R"({"terrain": {"generator": {}}, "render": )" + render +
           R"(, "path": {"keys": [{"t": 0, "position": [0, 0, 100]}]}})";
  };
  EXPECT_EQ(ig::io::parse_scenario(base).render.earth_curvature, "auto");
  EXPECT_EQ(ig::io::parse_scenario(with(R"({"earth_curvature": "on"})")).render.earth_curvature, "on");
  EXPECT_EQ(ig::io::parse_scenario(with(R"({"earth_curvature": "off"})")).render.earth_curvature, "off");
  try {
    ig::io::parse_scenario(with(R"({"earth_curvature": true})"));
    ADD_FAILURE() << "a boolean was accepted";
  } catch (const ig::io::ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("render.earth_curvature"), std::string::npos) << e.what();
  }

  ig::io::RenderSpec r;
  ig::io::TerrainSpec file, generated;
  file.file = "dem.tif";
  generated.generator = ig::options::SyntheticTerrainOptions{};
  auto hf = robustness::flat_terrain(257, 30.0, 0.0f);  // 7.7 km
  EXPECT_EQ(ig::session::earth_radius_for(r, file, hf), 0.0) << "auto: a DEM without georeference stays flat";
  hf.georef = ig::terrain::make_geographic_georef(46.5, 7.9, hf.spacing_x_m, hf.spacing_y_m);
  EXPECT_EQ(ig::session::earth_radius_for(r, file, hf), kEarthRadiusM) << "auto: georeferenced file wider than 5 km";
  EXPECT_EQ(ig::session::earth_radius_for(r, generated, hf), 0.0) << "auto: generated terrain is a flat synthetic world";
  auto small = robustness::flat_terrain(101, 30.0, 0.0f);  // 3 km
  small.georef = hf.georef;
  EXPECT_EQ(ig::session::earth_radius_for(r, file, small), 0.0) << "auto: georeferenced but under 5 km";
  r.earth_curvature = "on";
  EXPECT_EQ(ig::session::earth_radius_for(r, generated, small), kEarthRadiusM);
  r.earth_curvature = "off";
  EXPECT_EQ(ig::session::earth_radius_for(r, file, hf), 0.0);
}

}  // namespace
