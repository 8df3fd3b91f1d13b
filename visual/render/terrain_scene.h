#pragma once
// GPU-side terrain shared by every LOD method: the height texture, optional
// imagery, the shading parameters and the shading program's common uniforms.
// Methods own only their geometry and selection, so all of them shade alike.
//
// Height texture: R32F. Every int16 DEM height is exact in float32 and a
// float32 DEM keeps its own precision (24-bit mantissa: < 0.5 mm at 8848 m);
// R16 with scale/offset would quantise float DEMs (e.g. 0.07 m steps over a
// 4400 m range) for half the memory (4097^2: 64 MiB vs 32 MiB).
//
// Where the terrain sits: world_origin is the world position (double) of
// sample (0, 0) at height 0; methods work in terrain-local metres, and the
// FrameRenderer hands them local_camera(world camera), so an eye 1e7 m from
// the world origin is as precise as one at the origin. Earth curvature
// (terrain/earth_curvature.h) is a property of the scene too; it travels to
// the methods in Camera::earth_radius_m (culling) and to every terrain vertex
// shader through bind_common (u_earth_radius_m).

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "environment/sky_light.h"
#include "gl/gl_objects.h"
#include "gl/shader_program.h"
#include "lod/scene_requests.h"
#include "options/shading_options.h"
#include "render/height_window_texture.h"
#include "render/imagery_window_texture.h"
#include "render/camera.h"
#include "terrain/height_pyramid.h"
#include "terrain/heightfield.h"

namespace ig::render {

using ShadingParams = options::ShadingOptions;  // options/shading_options.h

class TerrainScene {
 public:
  // Side of the overview of a DEM beyond the GL texture limit, and of the
  // height window it then always has.
  static constexpr int kOverviewSide = 4097;
  static constexpr int kDefaultHeightWindow = 4096;
  // Paged heights: the window is made smaller when its tiles and the ring
  // around it would take more than half the memory budget (the window
  // refilling its own evicted tiles thrashes), but never below this: Level1's
  // largest square (1025) and its band.
  static constexpr int kMinPagedHeightWindow = 2048;
  // The largest DEM (samples) that gets a texture of its central
  // differences (height_differences_texture(): 4 bytes a sample, 256 MiB
  // at this size); larger ones read four heights for the normal.
  static constexpr long long kMaxHeightDifferencesSamples = 8193LL * 8193LL;

  // Uploads the height texture (and imagery, only when given). Throws
  // std::invalid_argument for a heightfield with fewer than 2 x 2 samples
  // (no surface to draw). A DEM larger than the GL texture limit gets an
  // overview texture (every overview_step()-th sample, at most
  // kOverviewSide a side) and a height window of kDefaultHeightWindow (less
  // for paged heights on a small budget, see kMinPagedHeightWindow):
  // only methods that draw through the window (twolevel) can draw it.
  // texture_limit > 0 lowers the GL limit used for that decision (tests).
  // Imagery beyond the limit is paged within imagery_budget_bytes (0: the
  // default of terrain::ImageryPaging).
  TerrainScene(const terrain::Heightfield& heightfield, const ShadingParams& shading,
               const std::optional<std::string>& imagery_path = std::nullopt, int texture_limit = 0,
               std::size_t imagery_budget_bytes = 0);
  TerrainScene(const TerrainScene&) = delete;
  TerrainScene& operator=(const TerrainScene&) = delete;

  const terrain::Heightfield& heightfield() const { return heightfield_; }
  const ShadingParams& shading() const { return shading_; }
  // Fog visibility in metres (0 = no fog); used from the next bind_common.
  void set_fog_visibility(double metres) { shading_.fog_visibility_m = metres; }
  // The fog's k (fog.frag: 1 - exp(-(k d)^2)) at the visibility now; 0: no fog.
  double fog_k() const;
  // The fragment stages of a terrain program: the shared shading
  // (terrain_shading.frag), the surface colour with or without ground detail
  // (ground_detail.frag / ground_plain.frag), the heights through a window
  // or from the whole DEM (height_at_window.frag / height_at_whole.frag),
  // imagery or none (imagery.frag / imagery_none.frag), the fog (fog.frag),
  // water or none (water_in_shading.frag with water.frag and
  // sky_colour.frag where the terrain pass shades it, water_none.frag without
  // water or with deferred shading, whose water pass draws it), then `own` (the
  // method's main and helpers). A CPU rasterizer runs both sides of a
  // branch, also on a uniform, so what is off or absent is not linked at all.
  // With deferred shading the stages store what the colour is a function of
  // (shade_deferred.frag) instead of computing it (shade_forward.frag).
  std::vector<std::string> shading_stages(const std::vector<std::string>& own) const;
  // The fragment stages of the deferred shading pass (deferred_shade.frag;
  // with water also marking where it may be, water_mark.frag).
  std::vector<std::string> deferred_shade_stages() const;
  // The fragment stages of deferred shading's water pass (gl/water_pass.h):
  // the marks into its depth mask (water_mask.frag) and its shading
  // (water_shade.frag); empty without water.
  std::vector<std::string> water_mask_stages() const;
  std::vector<std::string> water_shade_stages() const;
  // Whether the shading programs made from now on take the normal from the
  // DEM's central differences in one read (one texture of them, made with
  // the scene when the DEM fits one texture and kMaxHeightDifferencesSamples)
  // or from four height reads (always with an overview). The picture is the same within
  // the differences' half-float rounding; on by default where possible, off
  // for tests that compare the two.
  bool height_differences_texture() const { return use_height_differences_ && bool(height_differences_tex_); }
  void set_height_differences_texture(bool on) { use_height_differences_ = on; }
  // Whether the terrain programs made from now on shade deferred
  // (shading().deferred_shading; frames then need a single-sampled target).
  bool deferred_shading() const { return shading_.deferred_shading; }
  void set_deferred_shading(bool on) { shading_.deferred_shading = on; }
  // Ground detail for the programs made from now on (its texture made on first use).
  void set_ground_detail(bool on);
  // The light and sky (environment/sky_light.h) every terrain program and the
  // sky pass draw with: from shading().sun_direction (or the default sun)
  // until set_sun_direction moves the sun (the per-frame sun of a scenario's
  // time_utc); used from the next bind_common.
  const environment::SkyLight& sky_light() const { return sky_light_; }
  void set_sun_direction(const glm::vec3& towards_sun);
  const gl::Texture& height_texture() const { return height_tex_; }
  // DEM samples per height-texture sample: 1 when the texture is the whole
  // DEM, > 1 when it is an overview (the DEM exceeds the texture limit).
  int overview_step() const { return overview_step_; }
  // The largest height-texture side used (the GL limit, or the lower one given).
  int texture_limit() const { return texture_limit_; }
  // What the height texture holds: the DEM, or its overview
  // (terrain/heightfield_overview.h), e.g. to build Level0 on.
  const terrain::Heightfield& texture_heightfield() const { return overview_ ? *overview_ : heightfield_; }
  bool has_imagery() const { return bool(imagery_tex_); }
  // The terrain has water (heightfield().water): its share and wave
  // textures exist and the shading links water.frag.
  bool has_water() const { return bool(water_share_tex_); }
  // The scene's clock (sim time, seconds): the waves drift with it. Used
  // from the next bind_common.
  void set_time(double sim_time_s) { time_s_ = sim_time_s; }
  double time_s() const { return time_s_; }
  // The cloud layers drawn from the next frame (docs/rendering.md,
  // "Clouds"), each checked by environment::check_cloud_layer against the
  // terrain's lowest height; returns why each refused one was refused
  // ("cloud layer 2: negative thickness"). The constructor takes
  // shading.clouds the same way and throws std::invalid_argument on a refusal.
  std::vector<std::string> set_clouds(const options::CloudLayers& layers);
  const options::CloudLayers& clouds() const { return shading_.clouds; }
  // Imagery finer than the texture limit: the imagery texture is its
  // overview and this window holds full resolution around the point
  // follow_window() is given; null otherwise. Only methods that
  // call follow_window (twolevel) can draw it.
  const ImageryWindowTexture* imagery_window(int set = 0) const { return windows_[set].imagery.get(); }
  double upload_ms() const { return upload_ms_; }
  // Imagery texels of the DEM's footprint the image did not cover (grey).
  std::int64_t imagery_uncovered() const { return imagery_uncovered_; }
  // The min/max pyramid of the heightfield (ray casts, culling bounds),
  // built with the scene and shared by every method and channel on this scene:
  // it is view-independent (5.6 MB for a 4097^2 DEM, terrain/height_pyramid.h).
  const terrain::HeightPyramid& height_pyramid() const { return *pyramid_; }

  // Full-resolution heights around a point in a size x size wrap-around
  // texture (render/height_window_texture.h: terrain beyond one
  // texture). size <= 0: none (the default), except with an overview, which
  // always keeps a window (kDefaultHeightWindow when size <= 0). Without an
  // overview the whole-DEM texture stays and serves every read outside the
  // window, so every height is the same with or without the window; with
  // one, reads outside the window get the overview's (bilinear between its
  // samples for shading). A method that draws near one point (the
  // two-level method: Level1 and its band) keeps the window on it with
  // follow_window(), and reads through it (shaders/height_at_window.frag,
  // shaders/terrain_grid.vert). Call it before making the methods: their
  // programs link the window's reads only if the scene has a window then
  // (std::logic_error when a program was linked without them already).
  void enable_height_window(int size);
  // Each channel's view needs full resolution around its own Level1, so the
  // windows come in sets, one per method that draws through them (every
  // channel has its own method): claim_windows() gives a free set's index,
  // 0 first (the set the scene made), a new set of the same sizes when all
  // are in use; release_windows() frees it for the next method.
  int claim_windows();
  void release_windows(int set);
  int window_sets() const { return int(windows_.size()); }
  // Centres window set `set`'s height window on sample `centre` (clamped to
  // the DEM), uploading what scrolled in; returns the samples uploaded (0
  // without a window). Its imagery window, if any, follows too (its pixels
  // are not counted).
  long long follow_window(int set, glm::ivec2 centre);
  const HeightWindowTexture* height_window(int set = 0) const { return windows_[set].height.get(); }
  // Places every set's imagery window (if any) on sample `centre` ahead of
  // the first frame, so its first fill (and a tile of margin: the tiles are
  // read, the call waits) is part of the load, not of a frame.
  void place_imagery_window(glm::ivec2 centre);
  // Paged heights (terrain/paged_heights.h): asks the tile cache's background
  // thread for the tiles within half a tile of each point (terrain-local
  // metres), e.g. where the view rays hit, so next frame's ray casts find
  // them resident. Nothing for heights held whole.
  void prefetch_heights(const std::vector<glm::dvec3>& points_m);
  // The same for samples [lo, hi] (inclusive) and one tile around them.
  void prefetch_samples(glm::ivec2 lo, glm::ivec2 hi);
  // The frame's scene step: carries out what a method's update() asked
  // (lod/scene_requests.h) in its order: prefetches, then the window follows
  // (uploading what scrolled in), then the prefetch around square_and_band.
  void apply(const lod::SceneRequests& requests);
  // Paged heights: whether a frame may wait for tiles (a deterministic
  // replay) or must not (live: Level1 keeps its square until they are in;
  // render/twolevel_method.cpp). Default false.
  bool wait_for_pages() const { return wait_for_pages_; }
  void set_wait_for_pages(bool wait) { wait_for_pages_ = wait; }
  // Samples [lo, hi] (inclusive, clipped to the DEM) are all readable
  // without waiting on I/O (always true for heights held whole).
  bool samples_resident(glm::ivec2 lo, glm::ivec2 hi) const;
  // The samples follow_window(set, centre) would read with paged heights:
  // that set's height window centred there, inclusive (nullopt without a
  // height window or paging).
  std::optional<std::pair<glm::ivec2, glm::ivec2>> window_samples(int set, glm::ivec2 centre) const;

  // World position of sample (0, 0) at height 0 (default: the origin).
  const glm::dvec3& world_origin() const { return world_origin_; }
  void set_world_origin(const glm::dvec3& origin) { world_origin_ = origin; }
  // Sphere radius for the curvature drop; 0 = flat (default). Non-finite or
  // negative values mean flat.
  double earth_radius_m() const { return earth_radius_m_; }
  void set_earth_radius(double metres) { earth_radius_m_ = metres > 0.0 && std::isfinite(metres) ? metres : 0.0; }
  // The camera methods see: position relative to sample (0, 0) (computed in
  // double), earth_radius_m set from the scene.
  Camera local_camera(const Camera& world) const;

  // Binds the textures and sets the uniforms every terrain program shares
  // (see shaders/terrain.frag and terrain_grid.vert), u_earth_radius_m from
  // the (local) camera; the windows of set `windows` (claim_windows()), or
  // none (-1, methods that keep no window: whole heights, imagery overview).
  void bind_common(const gl::ShaderProgram& program, const Camera& camera, int windows = -1) const;

 private:
  // The fragment stages every shading program starts with, the water's
  // shading among them or not.
  std::vector<std::string> shading_library(bool with_water) const;
  // The heights: height_at_whole.frag or height_at_window.frag.
  const char* height_at_stage() const;
  // bind_common's part for programs linked with water.frag.
  void bind_water(const gl::ShaderProgram& program, const Camera& camera) const;

  const terrain::Heightfield& heightfield_;
  ShadingParams shading_;
  environment::SkyLight sky_light_;
  gl::Texture height_tex_;
  int overview_step_ = 1;
  int texture_limit_ = 0;
  bool wait_for_pages_ = false;
  std::unique_ptr<terrain::Heightfield> overview_;  // only beyond the texture limit
  gl::Texture imagery_tex_;  // empty without imagery
  gl::Texture detail_tex_;   // ground detail (terrain/detail_noise.h); empty when shading_.ground_detail is off
  gl::Texture height_differences_tex_;  // see height_differences_texture(); empty with an overview
  gl::Texture water_share_tex_;  // the share of water around each sample; empty without water
  gl::Texture waves_tex_;        // the waves' slopes; empty without water
  gl::Texture water_presence_tex_;  // where water may be (deferred shading's water pass); empty without water
  glm::ivec2 water_share_size_{0};
  double time_s_ = 0.0;
  bool use_height_differences_ = true;
  // A shading program was linked reading the whole DEM alone (no window).
  mutable bool linked_without_window_ = false;
  double upload_ms_ = 0.0;
  std::int64_t imagery_uncovered_ = 0;
  // Imagery beyond the limit: full-resolution pixels per overview pixel, and
  // the footprint over the overview's span (whole steps, so a little more
  // than the footprint; 1 for imagery that fits: u_imagery_overview_scale).
  int imagery_overview_step_ = 1;
  glm::vec2 imagery_overview_scale_{1.0f};
  std::unique_ptr<terrain::HeightPyramid> pyramid_;  // see height_pyramid()
  struct Windows {
    std::unique_ptr<HeightWindowTexture> height;    // see enable_height_window()
    std::unique_ptr<ImageryWindowTexture> imagery;  // see imagery_window()
  };
  std::vector<Windows> windows_ = std::vector<Windows>(1);  // see claim_windows()
  std::vector<bool> windows_in_use_ = std::vector<bool>(1, false);
  // Paged imagery beyond the texture limit, for the imagery windows of the
  // sets made after the first (its overview pixels dropped: they are the
  // imagery texture); null otherwise.
  std::unique_ptr<terrain::Imagery> window_imagery_;
  int imagery_window_side_ = 0;
  glm::dvec3 world_origin_{0.0};
  double earth_radius_m_ = 0.0;
};

}  // namespace ig::render
