// Precision far from the origin (issue 8, item 1). The terrain's world
// origin (TerrainScene::set_world_origin) and the camera are translated
// together by 1e5, 1e6 and 1e7 m in x, y and z: every method must draw the
// same picture (only silhouette pixels may differ) and the two-level method
// the same Level1 grid. Then the camera creeps forward 1 mm a frame at 1e7 m:
// the picture must follow smoothly (a float32 absolute position there has
// 1 m steps, so vertices would jump). 160 x 120 frames, a 257^2 DEM.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <optional>

#include "models/model_table.h"
#include "render/entity_renderer.h"
#include "robustness_support.h"
#include "water/water_map.h"

namespace {

using ig::render::Camera;
using robustness::Frame;
using robustness::Rig;

constexpr int kW = 160, kH = 120, kFrames = 4;

Camera base_camera(const ig::terrain::Heightfield& hf) {
  const double x = 1200.0, y = 1500.0;
  return robustness::camera_at({x, y, hf.sample_surface(x, y) + 150.0}, 40, -8);
}

// A pixel next to a silhouette or a depth step (> 5 %) in the base frame: a
// sub-pixel shift may flip it.
bool near_edge(const Frame& f, int x, int y) {
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int xx = x + dx, yy = y + dy;
      if (xx < 0 || yy < 0 || xx >= f.w || yy >= f.h) continue;
      if (f.terrain(xx, yy) != f.terrain(x, y)) return true;
      if (f.terrain(x, y) && std::abs(f.view_distance(xx, yy) / f.view_distance(x, y) - 1.0) > 0.05) return true;
    }
  return false;
}

TEST(Precision, TranslatedSceneRendersTheSameImageAndLevel1Grid) {
  // Every registered method in turn (one process per test keeps the label quick).
  for (const std::string& method : ig::render::method_names()) {
    SCOPED_TRACE(method);
    const auto hf = robustness::hills();
    const Camera cam0 = base_camera(hf);
    Frame base;
    glm::ivec2 base_origin{0};
    int base_n = 0;
    glm::dvec3 base_e{0.0};
    for (double offset : {0.0, 1e5, 1e6, 1e7}) {
      ig::render::TwoLevelOptions small;
      small.max_level1 = 65;  // a Level1 square well inside the DEM, so its origin means something
      Rig rig(hf, method, kW, kH, {}, small);
      const glm::dvec3 t(offset, offset, offset);
      rig.scene().set_world_origin(t);
      Camera cam = cam0;
      cam.position += t;
      const Frame f = rig.render(cam, kFrames);
      EXPECT_EQ(robustness::finite_problems(f), "") << "offset " << offset;
      auto* tl = robustness::as_twolevel(rig.method());
      if (offset == 0.0) {
        base = f;
        if (tl) {
          base_origin = tl->level1_origin();
          base_n = tl->level1_size();
          base_e = tl->look_at().point;
        }
        continue;
      }
      long long differing = 0, off_edge = 0;
      double worst_rel_depth = 0.0;
      for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
          const std::uint8_t *a = base.px(x, y), *b = f.px(x, y);
          const int diff = std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
          const bool same_kind = base.terrain(x, y) == f.terrain(x, y);
          if (same_kind && base.terrain(x, y))
            worst_rel_depth =
                std::max(worst_rel_depth, std::abs(f.view_distance(x, y) / base.view_distance(x, y) - 1.0));
          if (diff <= 2 && same_kind) continue;
          ++differing;
          off_edge += !near_edge(base, x, y);
        }
      std::printf("[precision] %-10s offset %.0e m: %lld pixels differ (%lld away from edges), worst |dD|/D %.2e",
                  method.c_str(), offset, differing, off_edge, worst_rel_depth);
      if (tl) {
        std::printf(", Level1 N=%d origin (%d,%d) E moved %.2e m", tl->level1_size(), tl->level1_origin().x,
                    tl->level1_origin().y, glm::length(tl->look_at().point - base_e));
        EXPECT_EQ(tl->level1_size(), base_n) << "offset " << offset;
        EXPECT_EQ(tl->level1_origin(), base_origin) << "offset " << offset;
        EXPECT_LT(glm::length(tl->look_at().point - base_e), 1e-3) << "offset " << offset;
      }
      std::printf("\n");
      EXPECT_EQ(off_edge, 0) << "offset " << offset << ": pixels changed away from silhouettes";
      EXPECT_LE(differing, kW * kH / 200) << "offset " << offset;
      EXPECT_LT(worst_rel_depth, 1e-4) << "offset " << offset;
    }
  }
}

// Water far from the origin: its shore, waves and glint come out the same
// (waves are placed from a whole sample near the eye, in double, as the
// ground detail is). A lake over the view's middle distance, drawn on the
// hills as they are.
TEST(Precision, WaterIsTheSameFarFromTheOrigin) {
  auto hf = robustness::hills();
  auto map = std::make_shared<ig::water::WaterMap>(hf.width, hf.height);
  ig::water::WaterBody lake;
  lake.level_m = 400.0f;
  map->bodies().push_back(lake);
  for (int j = 0; j < hf.height; ++j) {
    const std::vector<ig::water::WaterRun> runs =
        j >= 60 && j < 140 ? std::vector<ig::water::WaterRun>{{40, 200, 0}} : std::vector<ig::water::WaterRun>{};
    map->add_row(j, runs);
  }
  map->summarise_bodies(hf.spacing_x_m * hf.spacing_y_m);
  hf.water = map;
  for (const std::string method : {"twolevel", "reference"}) {
    SCOPED_TRACE(method);
    Frame base;
    for (double offset : {0.0, 1e7}) {
      Rig rig(hf, method, kW, kH);
      ASSERT_TRUE(rig.scene().has_water());
      const glm::dvec3 t(offset, offset, offset);
      rig.scene().set_world_origin(t);
      Camera cam = base_camera(hf);
      cam.position += t;
      const Frame f = rig.render(cam, kFrames);
      if (offset == 0.0) {
        base = f;
        // The view shows the lake: without it, much of the picture differs.
        auto dry = hf;
        dry.water.reset();
        Rig without(dry, method, kW, kH);
        const Frame d = without.render(base_camera(hf), kFrames);
        long long wet = 0;
        for (int y = 0; y < kH; ++y)
          for (int x = 0; x < kW; ++x) wet += std::abs(d.px(x, y)[2] - base.px(x, y)[2]) > 8;
        EXPECT_GT(wet, kW * kH / 10);
        continue;
      }
      long long differing = 0, off_edge = 0;
      for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
          const std::uint8_t *a = base.px(x, y), *b = f.px(x, y);
          const int diff = std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
          if (diff <= 2 && base.terrain(x, y) == f.terrain(x, y)) continue;
          ++differing;
          off_edge += !near_edge(base, x, y);
        }
      std::printf("[precision] water, %-10s offset %.0e m: %lld pixels differ (%lld away from edges)\n", method.c_str(),
                  offset, differing, off_edge);
      EXPECT_EQ(off_edge, 0);
      EXPECT_LE(differing, kW * kH / 200);
    }
  }
}

// Entities far from the origin: an aircraft 60 m ahead and a ship 400 m
// ahead of the eye come out the same at 1e7 m (their matrices are made
// eye-relative in double before they become float).
TEST(Precision, EntitiesAreTheSameFarFromTheOrigin) {
  const auto hf = robustness::hills();
  std::optional<ig::models::ModelTable> table =
      ig::models::load_model_table(std::string(IG_BIN_DIR) + "/models/default_models.json");
  Frame base;
  for (double offset : {0.0, 1e7}) {
    Rig rig(hf, "twolevel", kW, kH);
    ig::render::EntityRenderer entities(robustness::shader_dir(), table);
    rig.renderer().set_entities(&entities);
    const glm::dvec3 t(offset, offset, offset);
    rig.scene().set_world_origin(t);
    Camera cam = base_camera(hf);
    cam.position += t;
    const glm::dvec3 f = cam.forward();
    entities.set_instances({{1, 1, cam.position + 60.0 * f, ig::io::attitude_from_hpr({40.0, 0.0, 0.0}), 1.0f, {}},
                            {2, 3, cam.position + 400.0 * f - glm::dvec3(0, 0, 20), cam.attitude, 1.0f, {}}});
    const Frame fr = rig.render(cam, kFrames);
    EXPECT_EQ(fr.result.entities.in_view, 2u);
    if (offset == 0.0) {
      base = fr;
      continue;
    }
    long long differing = 0;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        const std::uint8_t *a = base.px(x, y), *b = fr.px(x, y);
        differing += std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])}) > 2;
      }
    std::printf("[precision] entities, twolevel offset %.0e m: %lld pixels differ\n", offset, differing);
    EXPECT_LE(differing, kW * kH / 500);
  }
}

TEST(Precision, NoVertexJitterWhileCreepingByMillimetresAt1e7) {
  // Every registered method in turn (one process per test keeps the label quick).
  for (const std::string& method : ig::render::method_names()) {
    SCOPED_TRACE(method);
    constexpr int kSteps = 20;
    constexpr double kCreep = 0.001;  // metres per frame, along the view axis
    const auto hf = robustness::hills();
    std::vector<double> steps_at[2];
    double distance = 0.0, total[2] = {0.0, 0.0};
    for (int run = 0; run < 2; ++run) {
      const double offset = run == 0 ? 0.0 : 1e7;
      Rig rig(hf, method, kW, kH);
      const glm::dvec3 t(offset, offset, offset);
      rig.scene().set_world_origin(t);
      Camera cam = base_camera(hf);
      cam.position += t;
      const glm::dvec3 fwd = cam.forward();
      rig.render(cam, kFrames);  // settle the LOD state
      double prev = 0.0;
      for (int k = 0; k <= kSteps; ++k) {
        Camera c = cam;
        c.position += fwd * (kCreep * k);
        const Frame f = rig.render(c);
        ASSERT_EQ(robustness::finite_problems(f), "");
        ASSERT_TRUE(f.terrain(kW / 2, kH / 2));
        // Pixel (80, 60) looks along the view axis up to half a pixel, so its
        // surface point stays put and its distance shrinks by the creep.
        const double d = f.view_distance(kW / 2, kH / 2);
        if (k > 0) steps_at[run].push_back(d - prev);
        if (k == 0) distance = d;
        total[run] = d - distance;
        prev = d;
      }
    }
    double worst_dev = 0.0, worst_vs_origin = 0.0;
    for (size_t k = 0; k < steps_at[1].size(); ++k) {
      worst_dev = std::max(worst_dev, std::abs(steps_at[1][k] + kCreep));
      worst_vs_origin = std::max(worst_vs_origin, std::abs(steps_at[1][k] - steps_at[0][k]));
    }
    std::printf(
        "[precision] %-10s creep 1 mm/frame at 1e7 m, centre pixel %.0f m away: steps within %.3f mm of "
        "-1 mm, total %.2f mm over %d mm, largest difference from the same creep at the origin %.4f mm\n",
        method.c_str(), distance, worst_dev * 1e3, total[1] * 1e3, kSteps, worst_vs_origin * 1e3);
    // The GPU's float pipeline (eye-relative vertices, rasterised depth) is
    // good to about 1e-6 of the distance; far from the origin it is no worse:
    // the same creep gives the same steps as at the origin.
    EXPECT_LT(worst_vs_origin, 1e-5) << "precision lost far from the origin";
    EXPECT_LT(worst_dev, 0.5e-3 + 2e-6 * distance) << "the centre pixel's distance does not follow a 1 mm creep";
    EXPECT_NEAR(total[1], -kCreep * kSteps, 0.5e-3 + 2e-6 * distance);
  }
}

TEST(PrecisionFrame, LocalCameraSubtractsTheOriginInDouble) {
  robustness::ensure_gl();
  const auto hf = robustness::flat_terrain(17, 10.0, 0.0f);
  ig::render::TerrainScene scene(hf, {});
  for (double offset : {1e5, 1e6, 1e7}) {
    scene.set_world_origin({offset, -offset, offset});
    Camera world;
    world.position = glm::dvec3(offset + 123.4567, -offset + 89.0123, offset + 45.6789);
    const Camera local = scene.local_camera(world);
    // Rounding of the world position itself (ulp(1e7) = 1.9e-9 m) is all that is lost.
    EXPECT_NEAR(local.position.x, 123.4567, 4e-9);
    EXPECT_NEAR(local.position.y, 89.0123, 4e-9);
    EXPECT_NEAR(local.position.z, 45.6789, 4e-9);
    EXPECT_EQ(local.attitude, world.attitude);
  }
}

}  // namespace
