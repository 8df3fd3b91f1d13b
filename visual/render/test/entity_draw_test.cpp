// Entities as drawn: an aircraft (entity type 1, the default model table's
// glTF) 25 m above the ground point the eye looks at changes the frame only
// around where it projects; the same aircraft 100 m under the ground changes
// nothing (byte-identical frames). For every LOD method, near the eye and
// (two-level) far out in Level0; with the post filter and with
// multisampling. An unknown type is drawn as a box; a run without entities
// has no entity pass.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <set>

#include "io/scenario.h"
#include "render/test/frame_dump.h"
#include "render/test/headless_run.h"
#include "render/twolevel_method.h"
#include "session/scenario_runner.h"
#include "terrain/ray_cast.h"

namespace {

using ig::render::EntityInstance;
using ig::session::ScenarioRunner;

struct Frame {
  std::vector<std::uint8_t> rgba;
  ig::render::ViewResult view;
};

// The default flight's first pose pitched 25 degrees down: the ground the eye
// looks at is about 500 m ahead, where the aircraft spans some 10 pixels.
double g_pitch_deg = -25.0;  // the view's pitch in the frames below
ig::io::Pose looking_down(const ScenarioRunner& runner) {
  ig::io::Pose p = runner.pose_at(0.0);
  ig::io::Hpr hpr = ig::io::hpr_from_attitude(p.attitude);
  hpr.pitch_deg = g_pitch_deg;
  p.attitude = ig::io::attitude_from_hpr(hpr);
  return p;
}

Frame draw(ScenarioRunner& runner, std::vector<EntityInstance> entities) {
  runner.set_entities(std::move(entities));
  runner.render_pose(0, 0.0, looking_down(runner));
  const auto& ch = runner.channels().front();
  return {ch.target->read_rgba(), ch.last};
}

// The terrain point `along_m` ahead of the eye on the view's centre ray
// (flat terrain; the frame lowers it and the entity alike), or the first
// hit along the ray when along_m is 0.
glm::dvec3 ground_ahead(ScenarioRunner& runner, double along_m) {
  const auto& cam = runner.channels().front().camera;
  const auto& hf = runner.heightfield();
  if (along_m > 0.0) {
    glm::dvec3 p = cam.position + cam.forward() * along_m;
    p.z = hf.sample_surface(p.x, p.y);
    return p;
  }
  const auto hit = ig::terrain::cast_ray(hf, runner.scene().height_pyramid(), cam.position, cam.forward());
  EXPECT_TRUE(hit);
  return hit ? hit->point : cam.position;
}

// Pixels that differ, and how far the farthest is from (px, py).
struct Difference {
  long long pixels = 0;
  double farthest_px = 0.0;
  int min_alpha = 255, max_alpha = 0;  // the coverage code (terrain level) under the changed pixels
};
Difference compare(const Frame& a, const Frame& b, int w, glm::dvec2 at) {
  Difference d;
  for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
    if (a.rgba[i] == b.rgba[i] && a.rgba[i + 1] == b.rgba[i + 1] && a.rgba[i + 2] == b.rgba[i + 2]) continue;
    ++d.pixels;
    d.min_alpha = std::min<int>(d.min_alpha, b.rgba[i + 3]);
    d.max_alpha = std::max<int>(d.max_alpha, b.rgba[i + 3]);
    const glm::dvec2 p(double((i / 4) % std::size_t(w)) + 0.5, double((i / 4) / std::size_t(w)) + 0.5);
    d.farthest_px = std::max(d.farthest_px, glm::length(p - at));
  }
  return d;
}

// Where a world point lands in the frame (pixels, top row 0).
glm::dvec2 project(const ig::render::Camera& cam, const glm::dvec3& p, int w, int h) {
  const glm::vec4 clip = cam.view_projection() * glm::vec4(glm::vec3(p - cam.position), 1.0f);
  return {(clip.x / clip.w * 0.5 + 0.5) * w, (0.5 - clip.y / clip.w * 0.5) * h};
}

// type 1: the aircraft (12 m span); 3: the ship (60 m long).
void check_entity(const std::string& method, const std::string& aa, double along_m, std::uint16_t type = 1) {
  const int w = 320, h = 240;
  ig::io::Scenario s = ig::io::load_scenario(std::string(IG_SOURCE_DIR) + "/scenarios/default.json");
  s.render.antialiasing = aa;
  ScenarioRunner runner(s, headless_run(w, h, method));
  const Frame bare = draw(runner, {});
  for (const auto& p : bare.view.passes) EXPECT_NE(p.name, "entities");  // none in a run without entities
  const glm::dvec3 ground = ground_ahead(runner, along_m);
  const auto& cam = runner.channels().front().camera;
  const double distance = glm::length(ground - cam.position);
  EntityInstance above{1, type, ground + glm::dvec3(0, 0, 25.0), ig::io::attitude_from_hpr({30.0, 0.0, 0.0}), 1.0f, {}};
  const Frame with = draw(runner, {above});
  // Half the model's length at `distance`, and the anti-aliasing filter's reach.
  const double px_per_m = h / (2.0 * std::tan(glm::radians(cam.fov_y_deg) / 2.0)) / distance;
  const double reach = (type == 3 ? 35.0 : 10.0) * px_per_m + 4.0;
  glm::dvec3 drawn = above.position;  // lowered by the curvature drop as the terrain
  if (cam.earth_radius_m > 0) drawn.z -= std::pow(glm::length(glm::dvec2(drawn - cam.position)), 2) / (2 * cam.earth_radius_m);
  const Difference d = compare(bare, with, w, project(cam, drawn, w, h));
  std::printf("[entities] %s %s at %.0f m: %lld pixels changed, farthest %.1f px from the projected point (bound %.1f), "
              "terrain coverage code under them %d..%d\n",
              method.c_str(), aa.c_str(), distance, d.pixels, d.farthest_px, reach, d.min_alpha, d.max_alpha);
  EXPECT_GT(d.pixels, 0) << method << " " << aa << " " << along_m;
  EXPECT_LE(d.farthest_px, reach) << method << " " << aa << " " << along_m;
  EXPECT_EQ(with.view.entities.in_view, 1u);
  if (auto* two = dynamic_cast<ig::render::TwoLevelMethod*>(&runner.method())) {
    // Near the look-at point the entity stands on Level1; 6 km out, on Level0.
    const auto& hf = runner.heightfield();
    const glm::dvec2 sample(ground.x / hf.spacing_x_m, ground.y / hf.spacing_y_m);
    const glm::dvec2 lo(two->level1_origin()), hi = lo + double(two->level1_size());
    const bool on_level1 = sample.x >= lo.x && sample.x <= hi.x && sample.y >= lo.y && sample.y <= hi.y;
    std::printf("[entities] two-level: the entity stands on %s (Level1 %d samples)\n", on_level1 ? "Level1" : "Level0",
                two->level1_size());
    EXPECT_EQ(on_level1, along_m == 0.0);
    // The coverage code the entity pass leaves in alpha: the terrain level behind it.
    if (aa == "fxaa") {
      EXPECT_EQ(d.max_alpha, on_level1 ? 255 : 128);
    }
  }
  // 100 m under the ground: hidden, the frame unchanged to the byte.
  EntityInstance under = above;
  under.position = ground - glm::dvec3(0, 0, 100.0);
  const Frame hidden = draw(runner, {under});
  EXPECT_EQ(compare(bare, hidden, w, {}).pixels, 0) << method << " " << aa << " " << along_m;
}

TEST(Entities, DrawnAboveTheGroundHiddenUnderItForEveryMethod) {
  for (const char* method : {"twolevel", "cdlod", "chunked", "geomipmap", "quadtree", "roam"})
    check_entity(method, "fxaa", 0.0);
}

// In two-level's band: just outside the Level1 square, within the band's
// width, where Level0's pixels are shaded with the blended coordinate. The
// entity is drawn there 25 m up and hidden 100 m under the ground.
TEST(Entities, InTwoLevelsBand) {
  const int w = 320, h = 240;
  ig::io::Scenario s = ig::io::load_scenario(std::string(IG_SOURCE_DIR) + "/scenarios/default.json");
  ScenarioRunner runner(s, headless_run(w, h, "twolevel"));
  const Frame bare = draw(runner, {});
  auto* two = dynamic_cast<ig::render::TwoLevelMethod*>(&runner.method());
  ASSERT_NE(two, nullptr);
  const auto& hf = runner.heightfield();
  const auto& cam = runner.channels().front().camera;
  const int n = two->level1_size(), band = two->band_width_samples();
  ASSERT_GT(band, 0);
  // From the square's centre, along the view's heading, half a band beyond its far edge.
  const glm::dvec2 centre = (glm::dvec2(two->level1_origin()) + 0.5 * double(n - 1)) *
                            glm::dvec2(hf.spacing_x_m, hf.spacing_y_m);
  const glm::dvec2 heading = glm::normalize(glm::dvec2(cam.forward()));
  const double reach = 0.5 * double(n - 1) / std::max(std::abs(heading.x), std::abs(heading.y)) + 0.5 * band;
  const glm::dvec2 at = centre + heading * reach * hf.spacing_x_m;
  const glm::dvec3 ground(at, hf.sample_surface(at.x, at.y));
  EntityInstance above{1, 1, ground + glm::dvec3(0, 0, 25.0), ig::io::attitude_from_hpr({30.0, 0.0, 0.0}), 1.0f, {}};
  const Frame with = draw(runner, {above});
  const Difference d = compare(bare, with, w, project(cam, above.position, w, h));
  std::printf("[entities] two-level band (Level1 %d samples, band %d): %lld pixels changed, farthest %.1f px\n", n, band,
              d.pixels, d.farthest_px);
  EXPECT_GT(d.pixels, 0);
  EXPECT_LE(d.farthest_px, 10.0);
  EntityInstance under = above;
  under.position = ground - glm::dvec3(0, 0, 100.0);
  EXPECT_EQ(compare(bare, draw(runner, {under}), w, {}).pixels, 0);
}

TEST(Entities, TwoLevelsLevel0AndMultisampling) {
  g_pitch_deg = -12.0;
  check_entity("twolevel", "fxaa", 6000.0, 3);  // far beyond Level1: on Level0
  g_pitch_deg = -25.0;
  check_entity("twolevel", "msaa", 0.0);
}

TEST(Entities, AnUnknownTypeIsABoxAndSaidOnce) {
  const int w = 160, h = 120;
  ig::io::Scenario s = ig::io::load_scenario(std::string(IG_SOURCE_DIR) + "/scenarios/default.json");
  ScenarioRunner runner(s, headless_run(w, h, "twolevel"));
  draw(runner, {});
  const glm::dvec3 ground = ground_ahead(runner, 0.0);
  const EntityInstance unknown{5, 999, ground + glm::dvec3(0, 0, 2.0), {1, 0, 0, 0}, 1.0f, {}};
  const Frame f = draw(runner, {unknown, unknown});
  EXPECT_EQ(f.view.entities.in_view, 2u);
  EXPECT_EQ(f.view.entities.batches, 1u);  // one instanced batch for both
  EXPECT_EQ(f.view.entities.triangles, 24u);
  const auto messages = runner.entity_renderer()->take_messages();
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_NE(messages[0].find("entity type 999: no model"), std::string::npos) << messages[0];
  draw(runner, {unknown});
  EXPECT_TRUE(runner.entity_renderer()->take_messages().empty());
}

// Each of the default table's models close up, lit by the default sun: the
// fine level drawn, covering a share of the frame as its size says, with
// shading (not one flat colour). IG_ENTITY_DUMP=DIR writes the frames.
TEST(Entities, EachDefaultModelCloseUp) {
  const int w = 480, h = 270;
  ig::io::Scenario s = ig::io::load_scenario(std::string(IG_SOURCE_DIR) + "/scenarios/default.json");
  ScenarioRunner runner(s, headless_run(w, h, "twolevel"));
  g_pitch_deg = -10.0;
  draw(runner, {});
  const auto& cam = runner.channels().front().camera;
  struct Case { std::uint16_t type; double distance_m; const char* name; };
  for (const Case c : {Case{1, 30.0, "aircraft"}, Case{2, 15.0, "ground_vehicle"}, Case{3, 140.0, "ship"}}) {
    const glm::dvec3 at = cam.position + cam.forward() * c.distance_m;
    const EntityInstance e{7, c.type, at, ig::io::attitude_from_hpr({ig::io::hpr_from_attitude(cam.attitude).heading_deg + 60.0, 0.0, 0.0}), 1.0f, {}};
    const Frame bare = draw(runner, {});
    const Frame f = draw(runner, {e});
    dump_frame("IG_ENTITY_DUMP", f.rgba, w, h, std::string("entity_") + c.name);
    const Difference d = compare(bare, f, w, {});
    // Distinct colours among the changed pixels: lit faces, not a silhouette.
    std::set<std::uint32_t> colours;
    for (std::size_t i = 0; i < f.rgba.size(); i += 4)
      if (f.rgba[i] != bare.rgba[i] || f.rgba[i + 1] != bare.rgba[i + 1] || f.rgba[i + 2] != bare.rgba[i + 2])
        colours.insert(std::uint32_t(f.rgba[i]) << 16 | std::uint32_t(f.rgba[i + 1]) << 8 | f.rgba[i + 2]);
    std::printf("[entities] %s at %.0f m: %lld pixels (%.1f %% of the frame), %zu colours, %llu triangles drawn\n", c.name,
                c.distance_m, d.pixels, 100.0 * double(d.pixels) / (w * h), colours.size(),
                (unsigned long long)f.view.entities.triangles);
    EXPECT_GT(d.pixels, w * h / 200) << c.name;
    EXPECT_GT(colours.size(), 20u) << c.name;
  }
  g_pitch_deg = -25.0;
}

// A CIGI view riding on an entity (chase view): the camera is the entity's
// pose moved by the eye offset in its body axes; an entity the IG does not
// have leaves the view on the ownship.
TEST(Entities, AViewRidesOnItsEntity) {
  ig::io::Scenario s = ig::io::load_scenario(std::string(IG_SOURCE_DIR) + "/scenarios/default.json");
  ScenarioRunner runner(s, headless_run(160, 120, "twolevel"));
  const ig::io::Pose tanker{{7000.0, 4000.0, 900.0}, ig::io::attitude_from_hpr({90.0, 0.0, 0.0})};
  runner.set_entity_lookup([&](std::uint16_t id) -> std::optional<ig::io::Pose> {
    if (id == 5) return tanker;
    return std::nullopt;
  });
  auto& spec = runner.channels().front().spec;
  spec.entity = 5;
  spec.eye_offset_m = {-30.0, 0.0, -8.0};  // 30 m behind, 8 m above (z down)
  draw(runner, {});
  const auto& cam = runner.channels().front().camera;
  EXPECT_NEAR(cam.position.x, 6970.0, 1e-9);  // heading east: behind is west
  EXPECT_NEAR(cam.position.y, 4000.0, 1e-9);
  EXPECT_NEAR(cam.position.z, 908.0, 1e-9);
  EXPECT_NEAR(ig::io::hpr_from_attitude(cam.attitude).heading_deg, 90.0, 1e-9);
  spec.entity = 6;  // not placed: the ownship's pose, moved by the offset
  draw(runner, {});
  const ig::io::Pose own = looking_down(runner);
  EXPECT_NEAR(glm::length(runner.channels().front().camera.position - own.position), std::hypot(30.0, 8.0), 1e-6);
}

// Articulated parts move the nodes the model table names: the ground
// vehicle's turret turned 90 degrees changes the picture where the vehicle
// is; its gun disabled takes pixels away; an id the table does not name
// changes nothing.
TEST(Entities, ArticulatedPartsMoveTheirNodes) {
  const int w = 320, h = 180;
  ig::io::Scenario s = ig::io::load_scenario(std::string(IG_SOURCE_DIR) + "/scenarios/default.json");
  ScenarioRunner runner(s, headless_run(w, h, "twolevel"));
  g_pitch_deg = -10.0;
  draw(runner, {});
  const auto& cam = runner.channels().front().camera;
  const double heading = ig::io::hpr_from_attitude(cam.attitude).heading_deg;
  EntityInstance vehicle{9, 2, cam.position + cam.forward() * 14.0, ig::io::attitude_from_hpr({heading + 90.0, 0.0, 0.0}), 1.0f, {}};
  const Frame bare = draw(runner, {});
  const Frame rest = draw(runner, {vehicle});
  auto turned = vehicle;
  turned.parts = {{1, true, {0, 0, 0}, {0, 0, 90}}};  // turret: yaw 90
  const Frame turret = draw(runner, {turned});
  auto no_gun = vehicle;
  no_gun.parts = {{2, false, {0, 0, 0}, {0, 0, 0}}};  // gun hidden
  const Frame gunless = draw(runner, {no_gun});
  auto unknown = vehicle;
  unknown.parts = {{77, true, {5, 5, 5}, {40, 40, 40}}};
  const Frame same = draw(runner, {unknown});
  const long long drawn = compare(bare, rest, w, {}).pixels;
  const long long moved = compare(rest, turret, w, {}).pixels;
  const long long without_gun = compare(bare, gunless, w, {}).pixels;
  std::printf("[entities] vehicle: %lld pixels; turret turned 90 deg: %lld change; gun hidden: %lld pixels\n", drawn,
              moved, without_gun);
  EXPECT_GT(moved, 20);
  EXPECT_LT(moved, drawn + 50);  // only around the vehicle
  EXPECT_LT(without_gun, drawn);
  EXPECT_EQ(compare(rest, same, w, {}).pixels, 0);
  g_pitch_deg = -25.0;
}

// More entities in view than the per-view budget: the nearest are drawn,
// the farthest counted.
TEST(Entities, TheNearestWithinTheBudgetAreDrawn) {
  ig::io::Scenario s = ig::io::load_scenario(std::string(IG_SOURCE_DIR) + "/scenarios/default.json");
  ScenarioRunner runner(s, headless_run(160, 120, "twolevel"));
  draw(runner, {});
  ig::render::EntityRenderer budget(std::string(IG_BIN_DIR) + "/shaders", std::nullopt, {}, 3);
  runner.channels().front().renderer->set_entities(&budget);
  const auto& cam = runner.channels().front().camera;
  std::vector<EntityInstance> five;
  for (int k = 0; k < 5; ++k)
    five.push_back({std::uint16_t(k + 1), 1, cam.position + cam.forward() * (40.0 + 30.0 * k), cam.attitude, 1.0f, {}});
  budget.set_instances(five);
  runner.render_pose(0, 0.0, looking_down(runner));
  const auto& v = runner.channels().front().last;
  EXPECT_EQ(v.entities.in_view, 3u);
  EXPECT_EQ(v.entities.over_budget, 2u);
  runner.channels().front().renderer->set_entities(nullptr);
}

}  // namespace
