// Extreme views (issue 8, item 3), each a test, for every method that
// method_names() lists (twolevel, the product; reference, the ground truth;
// and any baseline registered there). Every case checks: no exception, no
// non-finite depth, no black (NaN) pixel, every method log column and the
// error bound finite, and a sensible image: terrain coverage per pixel
// against an exact ray cast of that pixel's ray (the reference must agree
// almost everywhere, LOD methods within a looser bound), plus what the case
// itself implies (all sky straight up, terrain on top when upside down...).
// Frames are 160 x 120, near 0.1 m, far 300 km. Figures are printed as
// "[matrix]" lines (docs/robustness.md).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <functional>

#include "robustness_support.h"
#include "terrain/dem_loader.h"

namespace {

using ig::render::Camera;
using ig::terrain::Heightfield;
using robustness::Frame;
using robustness::Rig;

constexpr int kW = 160, kH = 120;
constexpr int kFrames = 4;  // the two-level size controller reads last frame's counts

// Coverage of a rendered frame against exact ray casts of every pixel's ray.
struct Coverage {
  long long checked = 0;  // pixels away from silhouettes and the near/far planes
  long long holes = 0;    // ray hits the terrain, frame shows sky
  long long extras = 0;   // ray misses, frame shows terrain
  long long expected_terrain = 0;
  double mismatch() const { return checked ? double(holes + extras) / double(checked) : 0.0; }
};

Coverage coverage(const Frame& f, const Heightfield& hf) {
  const ig::terrain::HeightPyramid pyramid(hf);
  const Camera& c = f.camera;
  // -1: ambiguous (hit closer than 3x near or beyond 0.9 far), 0 sky, 1 terrain.
  std::vector<int> expect(size_t(f.w) * f.h);
  for (int y = 0; y < f.h; ++y)
    for (int x = 0; x < f.w; ++x) {
      const glm::dvec3 ray = c.pixel_ray(x, y, f.w, f.h);
      const auto hit = ig::terrain::cast_ray(hf, pyramid, c.position, ray);
      int e = 0;
      if (hit) {
        const double axial = hit->t * glm::dot(ray, c.forward());
        e = axial < 3.0 * c.near_m || axial > 0.9 * c.far_m ? -1 : 1;
      }
      expect[size_t(y) * f.w + x] = e;
    }
  Coverage cov;
  for (int y = 0; y < f.h; ++y)
    for (int x = 0; x < f.w; ++x) {
      const int e = expect[size_t(y) * f.w + x];
      if (e < 0) continue;
      bool edge = false;  // a silhouette within 2 pixels may go either way
      for (int dy = -2; dy <= 2 && !edge; ++dy)
        for (int dx = -2; dx <= 2 && !edge; ++dx) {
          const int xx = x + dx, yy = y + dy;
          if (xx < 0 || yy < 0 || xx >= f.w || yy >= f.h) continue;
          edge = expect[size_t(yy) * f.w + xx] != e;
        }
      if (edge) continue;
      ++cov.checked;
      cov.expected_terrain += e;
      if (e == 1 && !f.terrain(x, y)) ++cov.holes;
      if (e == 0 && f.terrain(x, y)) ++cov.extras;
    }
  return cov;
}

// Mean image row of terrain pixels minus that of sky pixels (negative: terrain above).
double terrain_row_bias(const Frame& f) {
  double st = 0, ss = 0;
  long long nt = 0, ns = 0;
  for (int y = 0; y < f.h; ++y)
    for (int x = 0; x < f.w; ++x) {
      if (f.terrain(x, y))
        st += y, ++nt;
      else
        ss += y, ++ns;
    }
  if (!nt || !ns) return 0.0;
  return st / nt - ss / ns;
}

bool is_ground_truth(const std::string& method) { return method == "reference"; }

// The allowed coverage mismatch: the reference draws the exact surface; LOD
// methods may move silhouettes by their geometric error.
double allowed_mismatch(const std::string& method) { return is_ground_truth(method) ? 0.005 : 0.10; }

// Every case runs every registered method, one after another (one process
// per case keeps the robustness label quick).
class ExtremeViews : public ::testing::Test {
 protected:
  // Renders the view, checks the common expectations and prints the matrix line.
  Frame check_view(const std::string& method, const std::string& case_name, Heightfield hf, const Camera& camera) {
    Rig rig(std::move(hf), method, kW, kH);
    const Frame f = rig.render(camera, kFrames);
    const std::string problems = robustness::finite_problems(f);
    EXPECT_EQ(problems, "") << case_name << " / " << method;
    const Coverage cov = coverage(f, rig.heightfield());
    std::printf(
        "[matrix] %-22s %-10s terrain %5.1f%% (ray cast %5.1f%%) mismatch %.4f (holes %lld, extra %lld of %lld) "
        "passes %-28s tris %lld bound %s px\n",
        case_name.c_str(), method.c_str(), 100.0 * f.terrain_pixels() / (f.w * f.h),
        cov.checked ? 100.0 * cov.expected_terrain / cov.checked : 0.0, cov.mismatch(), cov.holes, cov.extras,
        cov.checked, f.result.method.passes.c_str(), f.result.method.triangles,
        f.error_bound_px ? std::to_string(*f.error_bound_px).c_str() : "-");
    EXPECT_LE(cov.mismatch(), allowed_mismatch(method))
        << case_name << " / " << method << ": terrain coverage disagrees with the exact ray cast (holes " << cov.holes
        << ", extra " << cov.extras << " of " << cov.checked << ")";
    RecordProperty(case_name + " / " + method + " mismatch", std::to_string(cov.mismatch()));
    last_twolevel_e_ = std::nullopt;
    if (auto* tl = robustness::as_twolevel(rig.method())) {
      const auto& e = tl->look_at();
      EXPECT_TRUE(std::isfinite(e.point.x) && std::isfinite(e.point.y) && std::isfinite(e.point.z));
      const auto& h = rig.heightfield();
      EXPECT_TRUE(e.point.x >= 0 && e.point.x <= h.extent_x_m() && e.point.y >= 0 && e.point.y <= h.extent_y_m())
          << "E off the DEM: " << e.point.x << ", " << e.point.y;
      last_twolevel_e_ = e.point;
    }
    return f;
  }
  std::optional<glm::dvec3> last_twolevel_e_;
};

double surface(const Heightfield& hf, double x, double y) { return hf.sample_surface(x, y); }

// 257 x 257 samples at 30 m (7.68 km), heights 100 .. 1000 m.
Heightfield hills() { return robustness::hills(); }
glm::dvec3 centre_of(const Heightfield& hf, double agl) {
  const double x = 0.5 * hf.extent_x_m(), y = 0.5 * hf.extent_y_m();
  return {x, y, surface(hf, x, y) + agl};
}

// ------------------------------------------------------------------ attitude --

TEST_F(ExtremeViews, PitchUp90SeesOnlySky) {
  for (const std::string& method : ig::render::method_names()) {
    SCOPED_TRACE(method);
    const Heightfield hf = hills();
    const glm::dvec3 eye(3000, 3000, hf.max_m + 300.0);
    const Frame f = check_view(method, "pitch +90", hf, robustness::camera_at(eye, 30, 90));
    EXPECT_EQ(f.terrain_pixels(), 0);
    const auto e90 = last_twolevel_e_;
    // No gimbal jump: a hair below vertical looks the same (all sky), and E,
    // though not drawn, stays put.
    const Frame g = check_view(method, "pitch +89.99", hf, robustness::camera_at(eye, 30, 89.99));
    EXPECT_EQ(g.terrain_pixels(), 0);
    if (e90 && last_twolevel_e_) {
      EXPECT_LT(glm::length(*e90 - *last_twolevel_e_), 2.0 * hf.spacing_x_m) << "E jumps at pitch 90";
    }
  }
}

TEST_F(ExtremeViews, PitchDown90SeesOnlyTerrainWithoutGimbalJump) {
  for (const std::string& method : ig::render::method_names()) {
    SCOPED_TRACE(method);
    const Heightfield hf = hills();
    const glm::dvec3 eye = centre_of(hf, 500.0);
    const Frame f = check_view(method, "pitch -90", hf, robustness::camera_at(eye, 30, -90));
    EXPECT_EQ(f.terrain_pixels(), f.w * f.h);
    const Frame g = check_view(method, "pitch -89.99", hf, robustness::camera_at(eye, 30, -89.99));
    // The same picture, 0.01 degrees apart: every pixel's distance within 1 %.
    double worst = 0.0;
    for (int y = 0; y < f.h; ++y)
      for (int x = 0; x < f.w; ++x) {
        if (!f.terrain(x, y) || !g.terrain(x, y)) continue;
        worst = std::max(worst, std::abs(f.view_distance(x, y) - g.view_distance(x, y)) / f.view_distance(x, y));
      }
    std::printf("[matrix] pitch -90 vs -89.99: worst relative distance change %.4f\n", worst);
    EXPECT_LT(worst, 0.01);
  }
}

TEST_F(ExtremeViews, Roll180PutsTerrainOnTop) {
  for (const std::string& method : ig::render::method_names()) {
    SCOPED_TRACE(method);
    const Heightfield hf = hills();
    const Frame f = check_view(method, "roll 180", hf, robustness::camera_at(centre_of(hf, 200.0), 45, -10, 180));
    EXPECT_GT(f.terrain_pixels(), f.w * f.h / 4);
    EXPECT_LT(terrain_row_bias(f), -10.0) << "upside down: the terrain belongs in the upper part of the frame";
  }
}

TEST_F(ExtremeViews, ExactlyAtTheHorizon) {
  for (const std::string& method : ig::render::method_names()) {
    SCOPED_TRACE(method);
    const Heightfield hf = hills();
    // Above every height, level: no ray at or above the centre row can hit.
    const glm::dvec3 eye(0.25 * hf.extent_x_m(), 0.25 * hf.extent_y_m(), hf.max_m + 200.0);
    const Frame f = check_view(method, "at the horizon", hf, robustness::camera_at(eye, 45, 0));
    long long upper = 0;
    for (int y = 0; y < f.h / 2; ++y)
      for (int x = 0; x < f.w; ++x) upper += f.terrain(x, y);
    EXPECT_EQ(upper, 0) << "terrain above the horizon";
    EXPECT_GT(f.terrain_pixels(), 0);
  }
}

// ------------------------------------------------------------------ position --

TEST_F(ExtremeViews, EyeBelowTheTerrainSeesItsUnderside) {
  for (const std::string& method : ig::render::method_names()) {
    SCOPED_TRACE(method);
    const Heightfield hf = hills();
    // 50 m under the surface, level. Culling is off, so the underside shows
    // above (rays going up come out through the surface); rays going down
    // leave through the DEM's side and see the haze (sky colour).
    const Frame f = check_view(method, "eye below terrain", hf, robustness::camera_at(centre_of(hf, -50.0), 10, 0));
    EXPECT_GT(f.terrain_pixels(), 0);
    EXPECT_LT(terrain_row_bias(f), 0.0) << "the underside is above the eye";
  }
}

TEST_F(ExtremeViews, EyeOutsideTheDemLookingBack) {
  for (const std::string& method : ig::render::method_names()) {
    SCOPED_TRACE(method);
    const Heightfield hf = hills();
    const glm::dvec3 eye(-3000.0, 0.5 * hf.extent_y_m(), 1500.0);
    const Frame f = check_view(method, "outside, looking back", hf, robustness::camera_at(eye, 90, -12));
    EXPECT_GT(f.terrain_pixels(), f.w * f.h / 20);
    // Looking away from it: nothing.
    const Frame g = check_view(method, "outside, looking away", hf, robustness::camera_at(eye, 270, -12));
    EXPECT_EQ(g.terrain_pixels(), 0);
  }
}

TEST_F(ExtremeViews, EyeExactlyOnADemEdge) {
  for (const std::string& method : ig::render::method_names()) {
    SCOPED_TRACE(method);
    const Heightfield hf = hills();
    const double y = 128 * hf.spacing_y_m;  // on a sample row too
    const glm::dvec3 eye(0.0, y, surface(hf, 0.0, y) + 50.0);
    const Frame in = check_view(method, "on the west edge, in", hf, robustness::camera_at(eye, 90, -10));
    EXPECT_GT(in.terrain_pixels(), in.w * in.h / 4);
    check_view(method, "on the west edge, out", hf, robustness::camera_at(eye, 270, -10));
    // On the edge line and on the surface itself (0 m above ground), looking along the edge.
    check_view(method, "on the edge surface", hf, robustness::camera_at({0.0, y, surface(hf, 0.0, y)}, 0, -5));
  }
}

TEST_F(ExtremeViews, EyeExactlyOnADemCorner) {
  for (const std::string& method : ig::render::method_names()) {
    SCOPED_TRACE(method);
    const Heightfield hf = hills();
    const glm::dvec3 corner(hf.extent_x_m(), hf.extent_y_m(), 0.0);
    const Frame f = check_view(method, "on the NE corner", hf,
                               robustness::camera_at(corner + glm::dvec3(0, 0, hf.at(256, 256) + 30.0), 225, -8));
    EXPECT_GT(f.terrain_pixels(), f.w * f.h / 4);
    check_view(method, "on the SW corner, out", hf, robustness::camera_at({0, 0, hf.at(0, 0) + 30.0}, 225, -8));
  }
}

TEST_F(ExtremeViews, TenCentimetresAboveGround) {
  for (const std::string& method : ig::render::method_names()) {
    SCOPED_TRACE(method);
    // Flat ground: the bottom row's ground is 0.17 m away along the view axis,
    // beyond the 0.1 m near plane, so every bottom-row pixel is terrain.
    const Heightfield flat = robustness::flat_terrain(129, 30.0, 250.0f);
    const Frame f = check_view(method, "0.1 m AGL, flat", flat, robustness::camera_at(centre_of(flat, 0.1), 200, 0));
    for (int x = 0; x < f.w; ++x) EXPECT_TRUE(f.terrain(x, f.h - 1)) << "column " << x;
    // On a slope, ground rising towards a corner comes nearer than the near
    // plane and is clipped (sky shows through there): documented, not a hole.
    // Every bottom-row pixel whose exact hit lies beyond the near plane is terrain.
    const Heightfield hf = hills();
    const Frame g = check_view(method, "0.1 m AGL, hills", hf, robustness::camera_at(centre_of(hf, 0.1), 200, 0));
    const ig::terrain::HeightPyramid pyramid(hf);
    int clipped = 0;
    for (int x = 0; x < g.w; ++x) {
      const glm::dvec3 ray = g.camera.pixel_ray(x, g.h - 1, g.w, g.h);
      const auto hit = ig::terrain::cast_ray(hf, pyramid, g.camera.position, ray);
      ASSERT_TRUE(hit) << "column " << x;
      const double axial = hit->t * glm::dot(ray, g.camera.forward());
      if (axial < g.camera.near_m) {
        ++clipped;
      } else if (axial > 1.05 * g.camera.near_m) {
        EXPECT_TRUE(g.terrain(x, g.h - 1)) << "column " << x << " axial " << axial;
      }
    }
    std::printf("[matrix] 0.1 m AGL, hills: %d of %d bottom-row pixels have ground nearer than the near plane\n",
                clipped, g.w);
  }
}

TEST_F(ExtremeViews, HundredKilometresAboveGround) {
  for (const std::string& method : ig::render::method_names()) {
    SCOPED_TRACE(method);
    const Heightfield hf = hills();
    const Frame f = check_view(method, "100 km AGL", hf, robustness::camera_at(centre_of(hf, 100000.0), 0, -90));
    // 7.7 km seen from 100 km with a 60 degree FOV: about 6.7 % of the height, 45 pixels in all.
    EXPECT_GT(f.terrain_pixels(), 20);
    EXPECT_LT(f.terrain_pixels(), 200);
    EXPECT_TRUE(f.terrain(f.w / 2, f.h / 2));
  }
}

// ---------------------------------------------------------------- projection --

TEST_F(ExtremeViews, FieldOfViewOneDegree) {
  for (const std::string& method : ig::render::method_names()) {
    SCOPED_TRACE(method);
    const Heightfield hf = hills();
    const glm::dvec3 eye(-500.0, -500.0, 1200.0);
    const Frame f = check_view(method, "FOV 1", hf, robustness::camera_at(eye, 45, -8, 0, 1.0));
    EXPECT_GT(f.terrain_pixels(), 0);
  }
}

TEST_F(ExtremeViews, FieldOfViewHundredSeventyDegrees) {
  for (const std::string& method : ig::render::method_names()) {
    SCOPED_TRACE(method);
    const Heightfield hf = hills();
    const Frame f = check_view(method, "FOV 170", hf, robustness::camera_at(centre_of(hf, 150.0), 45, -20, 0, 170.0));
    EXPECT_GT(f.terrain_pixels(), f.w * f.h / 4);
    EXPECT_LT(f.terrain_pixels(), f.w * f.h);
  }
}

// ------------------------------------------------------------------ terrains --

TEST_F(ExtremeViews, OneByOneDemIsAClearError) {
  for (const std::string& method : ig::render::method_names()) {
    SCOPED_TRACE(method);
    // In memory: the scene refuses it (no surface to draw)...
    auto one = robustness::grid(1, 1, 30.0, "one-sample");
    one.finalize_stats();
    robustness::ensure_gl();
    try {
      Rig rig(one, method, kW, kH);
      ADD_FAILURE() << "a 1x1 terrain was accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("2 x 2"), std::string::npos) << e.what();
      std::printf("[matrix] 1x1 DEM (memory)  %-10s error: %s\n", method.c_str(), e.what());
    }
    // ... and so does the loader, for a file.
    const std::string path = (robustness::temp_dir() / "one.asc").string();
    std::ofstream(path) << "ncols 1\nnrows 1\nxllcorner 0\nyllcorner 0\ncellsize 30\nNODATA_value -9999\n123\n";
    try {
      (void)ig::terrain::load_dem(path);
      ADD_FAILURE() << "the loader accepted a 1x1 DEM";
    } catch (const ig::terrain::DemError& e) {
      EXPECT_NE(std::string(e.what()).find("2x2"), std::string::npos) << e.what();
    }
  }
}

TEST_F(ExtremeViews, TwoByTwoDem) {
  for (const std::string& method : ig::render::method_names()) {
    SCOPED_TRACE(method);
    Heightfield hf = robustness::grid(2, 2, 100.0, "two-by-two");
    hf.heights = {0.0f, 10.0f, 20.0f, 30.0f};
    hf.finalize_stats();
    const Frame f = check_view(method, "2x2 DEM", hf, robustness::camera_at({50, -150, 120}, 0, -30));
    EXPECT_GT(f.terrain_pixels(), 0);
    const Frame g = check_view(method, "2x2 DEM, above", hf, robustness::camera_at({50, 50, 300}, 0, -90));
    EXPECT_GT(g.terrain_pixels(), 0);
  }
}

TEST_F(ExtremeViews, PerfectlyFlatDem) {
  for (const std::string& method : ig::render::method_names()) {
    SCOPED_TRACE(method);
    const Heightfield hf = robustness::flat_terrain(257, 30.0, 500.0f);
    const Frame f = check_view(method, "flat DEM, grazing", hf, robustness::camera_at(centre_of(hf, 2.0), 30, 0));
    EXPECT_GT(f.terrain_pixels(), f.w * f.h / 3);
    check_view(method, "flat DEM, down", hf, robustness::camera_at(centre_of(hf, 300.0), 30, -35));
  }
}

TEST_F(ExtremeViews, FourKilometreCliffBetweenNeighbouringSamples) {
  for (const std::string& method : ig::render::method_names()) {
    SCOPED_TRACE(method);
    Heightfield hf = robustness::grid(129, 129, 30.0, "cliff");
    for (int j = 0; j < hf.height; ++j)
      for (int i = 0; i < hf.width; ++i) hf.ref(i, j) = i < 64 ? 0.0f : 4000.0f;
    hf.finalize_stats();
    // In the low west half, 500 m up, looking east at the cliff face 900 m away.
    const glm::dvec3 eye(1000.0, 1920.0, 500.0);
    const Frame f = check_view(method, "4000 m cliff", hf, robustness::camera_at(eye, 90, 10));
    EXPECT_TRUE(f.terrain(f.w / 2, f.h / 2)) << "the cliff face fills the centre";
    check_view(method, "4000 m cliff, above", hf, robustness::camera_at({1920, 1920, 6000}, 90, -60));
  }
}

TEST_F(ExtremeViews, DemWithNodataHoles) {
  for (const std::string& method : ig::render::method_names()) {
    SCOPED_TRACE(method);
    // A file with voids: the loader fills them (docs/terrain-data.md); the
    // filled surface renders like any other.
    const std::string path = (robustness::temp_dir() / "holes.asc").string();
    {
      std::ofstream o(path);
      const int n = 129;
      o << "ncols " << n << "\nnrows " << n << "\nxllcorner 0\nyllcorner 0\ncellsize 30\nNODATA_value -9999\n";
      for (int row = 0; row < n; ++row)
        for (int i = 0; i < n; ++i) {
          const bool hole = (std::abs(row - 40) < 12 && std::abs(i - 50) < 15) || (row + i) % 97 == 0 || row == 100;
          const double h = 300.0 + 200.0 * std::sin(i * 0.07) * std::cos(row * 0.05);
          o << (hole ? std::string("-9999") : std::to_string(h)) << (i + 1 < n ? ' ' : '\n');
        }
    }
    const Heightfield hf = ig::terrain::load_dem(path);
    EXPECT_GT(hf.nodata_count, 500);
    for (float h : hf.heights) ASSERT_TRUE(std::isfinite(h));
    std::printf("[matrix] nodata DEM: %lld voids filled, heights %.1f .. %.1f m\n", (long long)hf.nodata_count,
                hf.min_m, hf.max_m);
    const Frame f = check_view(method, "nodata holes", hf, robustness::camera_at({1900, 200, 900}, 0, -25));
    EXPECT_GT(f.terrain_pixels(), f.w * f.h / 2);
  }
}

}  // namespace
