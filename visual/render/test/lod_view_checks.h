#pragma once
// Shared by the image tests of the LOD baselines (roam_test, quadtree_test,
// geomipmap_test, chunked_test, cdlod_test): one headless GL context with a
// synthetic terrain, the views each method is checked at, rendering a method
// and the reference into the same small target, the hole count (terrain in
// the reference, sky in the method), and the checks several methods share.
//
// With IG_LOD_DUMP=<dir> set, frames are written there as PNG for a look.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "render/test/frame_dump.h"
#include "render/test/target_pixels.h"
#include "capture/png_writer.h"
#include "gl/gl_context.h"
#include "gl/render_target.h"
#include "io/pose.h"
#include "render/frame_renderer.h"
#include "render/reference_method.h"
#include "render/terrain_method.h"
#include "render/terrain_scene.h"
#include "render/twolevel_method.h"  // make_method() takes TwoLevelOptions
#include "terrain/synthetic_terrain.h"
#include "lod/test/lod_test_terrain.h"
#include "session/view_step.h"

namespace lod_views {

constexpr int kW = 320, kH = 240;

struct World {
  std::unique_ptr<ig::gl::GlContext> context;
  ig::terrain::Heightfield hf;
  std::unique_ptr<ig::render::TerrainScene> scene;
  std::string shader_dir = std::string(IG_BIN_DIR) + "/shaders";
  std::unique_ptr<ig::gl::RenderTarget> target;

  // 513 x 513 samples at 30 m (15.4 km square, 1500 m relief): the default
  // landscape at half resolution, big enough for several LOD levels.
  explicit World(int size = 513, unsigned seed = ig::options::SyntheticTerrainOptions{}.seed)
      : context(ig::gl::create_headless_context()) {
    ig::options::SyntheticTerrainOptions p;
    p.size = size;
    p.seed = seed;
    hf = ig::terrain::generate_synthetic_terrain(p);
    scene = std::make_unique<ig::render::TerrainScene>(hf, ig::render::ShadingParams{});
    target = std::make_unique<ig::gl::RenderTarget>(kW, kH);
  }
};

// A heightfield of any size with sharp detail (sizes not 2^n + 1, non-square).
inline ig::terrain::Heightfield bumpy(int w, int h) {
  auto hf = lod_checks::heightfield_from(w, h, 30.0, 30.0, [](int i, int j) {
    return 400.0 + 250.0 * std::sin(0.05 * i) * std::cos(0.07 * j) + 30.0 * std::sin(0.9 * i + 0.5 * j);
  });
  hf.source = "bumpy(" + std::to_string(w) + "x" + std::to_string(h) + ")";
  return hf;
}

// An eye `agl` metres above the surface at (x, y), looking along heading /
// pitch (degrees; io/pose.h convention).
inline ig::render::Camera camera_at(const ig::terrain::Heightfield& hf, double x, double y, double agl,
                                    double heading, double pitch) {
  ig::render::Camera c;
  c.position = {x, y, hf.sample_surface(x, y) + agl};
  c.attitude = ig::io::attitude_from_hpr({heading, pitch, 0.0});
  c.fov_y_deg = 60.0;
  c.aspect = double(kW) / kH;
  return c;
}

// An eye `distance` metres from the DEM's centre (at its mean height),
// looking at it along heading / pitch: the whole of a small DEM in view.
inline ig::render::Camera camera_looking_at_centre(const ig::terrain::Heightfield& hf, double distance,
                                                   double heading, double pitch) {
  ig::render::Camera c = camera_at(hf, 0, 0, 0, heading, pitch);
  const glm::dvec3 centre(0.5 * hf.extent_x_m(), 0.5 * hf.extent_y_m(), hf.mean_m);
  c.position = centre - c.forward() * distance;
  return c;
}

struct View {
  std::string name;
  ig::render::Camera camera;
};

// Low-altitude grazing, 30 degrees down, straight down, and along the DEM's
// west edge (looking north, a little outward, so the edge and the void
// beyond it are in view).
inline std::vector<View> views(const ig::terrain::Heightfield& hf) {
  const double ex = hf.extent_x_m(), ey = hf.extent_y_m();
  return {{"grazing", camera_at(hf, 0.25 * ex, 0.2 * ey, 100.0, 40.0, -4.0)},
          {"pitch30", camera_at(hf, 0.6 * ex, 0.55 * ey, 600.0, 200.0, -30.0)},
          {"down", camera_at(hf, 0.5 * ex, 0.5 * ey, 1500.0, 0.0, -90.0)},
          {"edge", camera_at(hf, 5 * hf.spacing_x_m, 0.3 * ey, 150.0, 345.0, -8.0)}};
}

// The views the per-frame baselines (ROAM, quadtree) are checked at: low
// grazing flight, 30 degrees down, straight down, and near the DEM's east
// edge looking out over it (the terrain ends in the image).
inline std::vector<View> per_frame_views(const ig::terrain::Heightfield& hf) {
  const double ex = hf.extent_x_m(), ey = hf.extent_y_m();
  return {{"grazing", camera_at(hf, 0.45 * ex, 0.3 * ey, 100.0, 20.0, -3.0)},
          {"pitch30", camera_at(hf, 0.6 * ex, 0.55 * ey, 600.0, 200.0, -30.0)},
          {"down", camera_at(hf, 0.3 * ex, 0.7 * ey, 1500.0, 0.0, -90.0)},
          {"edge", camera_at(hf, 0.98 * ex, 0.5 * ey, 300.0, 80.0, -15.0)}};
}

struct Frame : TargetPixels {
  ig::render::MethodFrameStats stats;
  double lod_ms = 0.0;
  double bound_px = 0.0;
};

// One context and 513 x 513 terrain for a whole test binary (one GL context per process).
inline World& shared_world() {
  static World w(513, 4);
  return w;
}

inline void dump(const Frame& f, const std::string& name) { dump_frame("IG_LOD_DUMP", f.rgba, f.w, f.h, name); }

// Renders one view of `scene` (world.scene unless given) with the method.
inline Frame render(World& world, ig::render::TerrainMethod& method, const ig::render::Camera& camera,
                    ig::render::TerrainScene* scene = nullptr) {
  if (!scene) scene = world.scene.get();
  ig::render::FrameRenderer renderer(*scene, method, world.shader_dir);
  const auto r = ig::session::render_view(*scene, renderer, camera, *world.target);
  Frame f;
  f.read(*world.target);
  f.stats = r.method;
  f.lod_ms = r.timings.lod_ms;
  f.bound_px = method.error_bound_px(scene->local_camera(camera), f.h).value_or(-1.0);
  return f;
}

// Holes allowed per 320 x 240 view. Neighbouring pieces compute a shared
// vertex from different origins (eye-relative floats), so a rare isolated
// pixel may slip between them (the reference's own chunks have the same
// property); a real crack is a line of pixels: with GeoMipMapping's
// stitching switched off the views here show 21 to 150 holes.
constexpr long long kHoleTolerance = 3;

struct HoleCount {
  long long reference_terrain = 0;  // terrain pixels of the reference
  long long checked = 0;            // of those, away from the reference's sky silhouette
  long long holes = 0;              // checked pixels that show sky in the method's frame
  long long silhouette = 0;         // unchecked pixels that show sky in the method's frame (reported, not failed)
  long long black = 0;              // unshaded pixels anywhere (NaN shading, holes in the sky pass)
  long long nan_depth = 0;
  std::string where;                // the first few holes, "x,y" (for failure messages)
};

// A reference terrain pixel with reference sky within band_rows rows (and a
// column) of it lies on the horizon silhouette: a coarser mesh may lower a
// ridge there by up to its error, so those pixels may show sky legitimately.
inline HoleCount count_holes(const Frame& ref, const Frame& m, int band_rows) {
  HoleCount c;
  const int w = ref.w, h = ref.h;
  auto near_sky = [&](int x, int y) {
    for (int dy = -band_rows; dy <= band_rows; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int xx = x + dx, yy = y + dy;
        if (xx >= 0 && yy >= 0 && xx < w && yy < h && !ref.terrain(xx, yy)) return true;
      }
    return false;
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t p = size_t(y) * w + x;
      if (!std::isfinite(m.depth[p])) ++c.nan_depth;
      if (int(m.rgba[p * 4]) + m.rgba[p * 4 + 1] + m.rgba[p * 4 + 2] < 12) ++c.black;
      if (!ref.terrain(x, y)) continue;
      ++c.reference_terrain;
      if (near_sky(x, y)) {
        c.silhouette += !m.terrain(x, y);
        continue;
      }
      ++c.checked;
      if (m.terrain(x, y)) continue;
      if (++c.holes <= 5) c.where += std::to_string(x) + "," + std::to_string(y) + " ";
    }
  return c;
}

// ---- Checks of the per-frame baselines (ROAM, quadtree) ----

// Renders the view with the reference and the method: the view shows
// terrain, the method draws triangles, the claimed bound is finite and
// >= 0, and no reference terrain pixel shows sky outside the silhouette band
// (the error bound plus 2 rows for rasterisation at the edge).
// `forced_column` names the method's forced-split column, for the figures.
inline void expect_no_holes_within_bound(World& world, ig::render::TerrainMethod& reference,
                                         ig::render::TerrainMethod& method, const View& v, size_t forced_column) {
  const Frame ref = render(world, reference, v.camera);
  const Frame f = render(world, method, v.camera);
  const double bound = *method.error_bound_px(v.camera, kH);
  ASSERT_TRUE(std::isfinite(bound)) << v.name;
  ASSERT_GE(bound, 0.0) << v.name;
  const int band = 2 + int(std::ceil(bound));
  const auto h = count_holes(ref, f, band);
  std::printf("%-8s tris %7lld  forced %5.0f  bound %5.2f px  holes %lld  silhouette sky %lld of %lld\n",
              v.name.c_str(), f.stats.triangles, f.stats.columns[forced_column].second, bound, h.holes,
              h.silhouette, h.reference_terrain);
  EXPECT_GT(h.reference_terrain, kW * kH / 10) << v.name << ": the view should show terrain";
  EXPECT_GT(f.stats.triangles, 0) << v.name;
  EXPECT_EQ(h.holes, 0) << v.name << ": sky through the surface";
}

// expect_no_holes_within_bound at every view of per_frame_views(w.hf), each
// followed by `also(view)`: the method's own checks at that view.
template <class Also>
void expect_no_holes_at_per_frame_views(World& w, ig::render::TerrainMethod& method, size_t forced_column, Also also) {
  ig::render::ReferenceMethod reference(*w.scene, w.shader_dir);
  for (const auto& v : per_frame_views(w.hf)) {
    ASSERT_NO_FATAL_FAILURE(expect_no_holes_within_bound(w, reference, method, v, forced_column));
    also(v);
  }
}

// The registry's knob sweep of `method_name` at the grazing and pitch30
// views: strictly more triangles and a bound never larger at each step, and
// at the end a strictly smaller bound than at the start unless the start
// already sits on the full-resolution floor (`finest_knob`; the cells split
// across the reference's diagonal right under the eye, which no setting can
// remove).
inline void expect_sweep_refines_down_to_the_floor(World& w, const std::string& method_name,
                                                   const std::string& knob_label, double finest_knob) {
  const auto sweep = ig::render::knob_sweep(method_name);
  ASSERT_GE(sweep.size(), 5u);
  for (const auto& v : per_frame_views(w.hf)) {
    if (v.name != "grazing" && v.name != "pitch30") continue;
    long long prev_tris = 0;
    double prev_bound = std::numeric_limits<double>::infinity(), first_bound = 0.0, last_bound = 0.0;
    for (double knob : sweep) {
      auto method = ig::render::make_method(method_name, *w.scene, w.shader_dir, {}, knob);
      ASSERT_EQ(method->knob()->value, knob);
      const Frame f = render(w, *method, v.camera);
      const double bound = *method->error_bound_px(v.camera, kH);
      std::printf("%-8s %s %4.1f  tris %7lld  bound %6.3f px\n", v.name.c_str(), knob_label.c_str(), knob,
                  f.stats.triangles, bound);
      EXPECT_GT(f.stats.triangles, prev_tris) << v.name << " " << knob_label << " " << knob;
      EXPECT_TRUE(std::isfinite(bound));
      EXPECT_GE(bound, 0.0);
      EXPECT_LE(bound, prev_bound * (1 + 1e-9)) << v.name << " " << knob_label << " " << knob;
      prev_tris = f.stats.triangles;
      prev_bound = bound;
      if (knob == sweep.front()) first_bound = bound;
      last_bound = bound;
    }
    auto finest = ig::render::make_method(method_name, *w.scene, w.shader_dir, {}, finest_knob);
    render(w, *finest, v.camera);
    const double floor_px = *finest->error_bound_px(v.camera, kH);
    std::printf("%-8s full-resolution floor %6.3f px\n", v.name.c_str(), floor_px);
    EXPECT_GE(last_bound, floor_px * (1 - 1e-9)) << v.name;
    if (first_bound > floor_px * (1 + 1e-6)) {
      EXPECT_LT(last_bound, first_bound) << v.name;
    }
  }
}

// ---- Checks of the baselines with precomputed pieces (GeoMipMapping,
// chunked LOD, CDLOD) ----

// A test suite with the default world and the reference's frames at views(),
// rendered once for all its tests.
class ReferenceFramesTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    world_ = new World();
    ig::render::ReferenceMethod reference(*world_->scene, world_->shader_dir);
    for (const auto& v : views(world_->hf)) {
      reference_->push_back(render(*world_, reference, v.camera));
      dump(reference_->back(), "reference_" + v.name);
    }
  }
  static void TearDownTestSuite() {
    delete world_;
    world_ = nullptr;
  }
  static inline World* world_ = nullptr;
  static inline std::vector<Frame>* reference_ = new std::vector<Frame>();
};

// The method's frame against the reference's at the same view (3-row
// silhouette band): enough pixels checked, holes within the tolerance, no
// black pixels, no NaN depth.
inline HoleCount expect_no_holes(const Frame& reference, const Frame& f, const std::string& view_name) {
  const auto c = count_holes(reference, f, 3);
  EXPECT_GT(c.checked, 1000) << view_name;
  EXPECT_LE(c.holes, kHoleTolerance) << view_name << ": terrain in the reference, sky here at " << c.where;
  EXPECT_EQ(c.black, 0) << view_name;
  EXPECT_EQ(c.nan_depth, 0) << view_name;
  return c;
}

// Every view of views(world.hf) rendered with `method`, dumped as
// "NAME_VIEW", and expect_no_holes against its reference frame; `each(view
// name, frame)` adds the method's own checks of the frame.
template <class Each>
void expect_every_view_without_holes(World& world, const std::vector<Frame>& reference,
                                     ig::render::TerrainMethod& method, const std::string& name, Each each) {
  const auto all = views(world.hf);
  for (size_t k = 0; k < all.size(); ++k) {
    const Frame f = render(world, method, all[k].camera);
    dump(f, name + "_" + all[k].name);
    const auto c = expect_no_holes(reference[k], f, all[k].name);
    std::printf("%s %-8s triangles %lld  bound %.2f px  terrain %lld checked %lld holes %lld %s\n", name.c_str(),
                all[k].name.c_str(), f.stats.triangles, f.bound_px, c.reference_terrain, c.checked, c.holes,
                c.where.c_str());
    each(all[k].name, f);
  }
}

// Follows a knob sweep from least to most accurate at one view: triangles
// never fewer and the claimed bound finite, >= 0 and never larger at each
// step; over the sweep more than twice the triangles and a smaller bound.
class SweepChecks {
 public:
  SweepChecks(std::string view_name, std::string knob_label)
      : view_(std::move(view_name)), knob_(std::move(knob_label)) {}

  void add(const Frame& f, double knob) {
    EXPECT_TRUE(std::isfinite(f.bound_px));
    EXPECT_GE(f.bound_px, 0.0);
    EXPECT_GE(f.stats.triangles, previous_triangles_) << view_ << " " << knob_ << " " << knob;
    EXPECT_LE(f.bound_px, previous_bound_) << view_ << " " << knob_ << " " << knob;
    if (first_triangles_ == 0) {
      first_triangles_ = f.stats.triangles;
      first_bound_ = f.bound_px;
    }
    previous_triangles_ = f.stats.triangles;
    previous_bound_ = f.bound_px;
  }

  void finish() const {
    EXPECT_GT(previous_triangles_, 2 * first_triangles_) << view_;
    EXPECT_LT(previous_bound_, first_bound_) << view_;
  }

 private:
  std::string view_, knob_;
  long long previous_triangles_ = 0, first_triangles_ = 0;
  double previous_bound_ = 1e300, first_bound_ = 0.0;
};

// Registered under `name` with a knob `knob_name` taking `knob_value`, and a
// sweep of at least 5 settings from least to most accurate (`finer_is_larger`:
// the knob grows along it, else it shrinks).
inline void expect_registered_with_knob(const World& world, const std::string& name, const std::string& knob_name,
                                        double knob_value, bool finer_is_larger) {
  const auto names = ig::render::method_names();
  EXPECT_NE(std::find(names.begin(), names.end(), name), names.end());
  const auto m = ig::render::make_method(name, *world.scene, world.shader_dir, {}, knob_value);
  ASSERT_TRUE(m->knob().has_value());
  EXPECT_EQ(m->knob()->name, knob_name);
  EXPECT_EQ(m->knob()->value, knob_value);
  const auto sweep = ig::render::knob_sweep(name);
  ASSERT_GE(sweep.size(), 5u);
  for (size_t k = 1; k < sweep.size(); ++k) {
    if (finer_is_larger) {
      EXPECT_GT(sweep[k], sweep[k - 1]) << "least to most accurate";
    } else {
      EXPECT_LT(sweep[k], sweep[k - 1]) << "least to most accurate";
    }
  }
}

// `name` registered with its default knob `knob_name` = `default_value` and
// `columns` log columns; make_method refuses `bad_knob` and NaN.
inline void expect_registered_with_default_knob(const World& world, const std::string& name,
                                                const std::string& knob_name, double default_value, size_t columns,
                                                double bad_knob) {
  const auto names = ig::render::method_names();
  EXPECT_NE(std::find(names.begin(), names.end(), name), names.end());
  auto m = ig::render::make_method(name, *world.scene, world.shader_dir, {});
  EXPECT_EQ(m->name(), name);
  ASSERT_TRUE(m->knob().has_value());
  EXPECT_EQ(m->knob()->name, knob_name);
  EXPECT_EQ(m->knob()->value, default_value);
  EXPECT_EQ(m->column_names().size(), columns);
  EXPECT_THROW(ig::render::make_method(name, *world.scene, world.shader_dir, {}, bad_knob), std::invalid_argument);
  EXPECT_THROW(ig::render::make_method(name, *world.scene, world.shader_dir, {}, std::nan("")), std::invalid_argument);
}

// DEMs of odd sizes (not 2^n + 1, non-square, tiny) rendered with the method
// `make` builds for their scene and with the reference, each seen whole: holes
// within the tolerance, no black pixels, some triangles. `also` adds the
// method's own checks of its frame.
using MakeMethod = std::function<std::unique_ptr<ig::render::TerrainMethod>(const ig::render::TerrainScene&)>;
inline void expect_odd_sized_dems_render_without_holes(
    World& world, const MakeMethod& make,
    const std::function<void(const Frame&, const ig::terrain::Heightfield&)>& also = nullptr) {
  for (auto [w, h] : {std::pair{65, 65}, std::pair{101, 77}, std::pair{3, 2}, std::pair{150, 40}}) {
    const auto hf = bumpy(w, h);
    ig::render::TerrainScene scene(hf, ig::render::ShadingParams{});
    const auto method = make(scene);
    ig::render::ReferenceMethod reference(scene, world.shader_dir);
    const auto cam =
        camera_looking_at_centre(hf, 1.5 * std::max(hf.extent_x_m(), hf.extent_y_m()) + 100.0, 30.0, -35.0);
    const Frame r = render(world, reference, cam, &scene);
    const Frame f = render(world, *method, cam, &scene);
    const auto c = count_holes(r, f, 3);
    EXPECT_LE(c.holes, kHoleTolerance) << hf.source;
    EXPECT_EQ(c.black, 0) << hf.source;
    EXPECT_GT(f.stats.triangles, 0) << hf.source;
    if (also) also(f, hf);
  }
}

}  // namespace lod_views
