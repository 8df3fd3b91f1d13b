#include "render/terrain_scene.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "environment/cloud_layers.h"
#include "gl/coverage_codes.h"
#include "gl/gl_context.h"
#include "gl/frame_state.h"
#include "gl/sky_pass.h"
#include "gl/terrain_textures.h"
#include "gl/water_textures.h"
#include "terrain/detail_noise.h"
#include "terrain/heightfield_overview.h"
#include "terrain/imagery_loader.h"
#include "terrain/paged_heights.h"
#include "water/shore_field.h"
#include "water/water_map.h"
#include "water/water_presence.h"
#include "water/wave_slopes.h"

namespace ig::render {
namespace {
// Ground detail tile sizes (metres a texture repeat): fine grain and clumps,
// the same at an unrelated size so no repeat shows, broad patches.
constexpr float kDetailTileM[3] = {32.0f, 87.3f, 2048.0f};

gl::Texture upload_detail_texture() {
  const terrain::DetailNoise noise = terrain::make_detail_noise();
  return gl::upload_colour_texture(noise.size, noise.size, noise.rgba.data(), /*rgba=*/true, /*repeat=*/true);
}

// The share of water around each sample of the height texture's grid (every
// `step`-th DEM sample), row by row, each row also given to `presence`.
gl::Texture upload_water_share(const water::WaterMap& map, int step, water::PresenceBuilder& presence) {
  const water::ShoreGrid g = water::shore_grid(map, step);
  return gl::upload_water_share_texture(g.width, g.height, [&](const auto& sink) {
    water::for_each_shore_row(map, step, [&](int j, const std::uint8_t* share, const std::uint8_t*) {
      sink(j, share);
      presence.add_row(j, share);
    });
  });
}
}  // namespace

TerrainScene::TerrainScene(const terrain::Heightfield& hf, const ShadingParams& shading,
                           const std::optional<std::string>& imagery_path, int texture_limit,
                           std::size_t imagery_budget_bytes)
    : heightfield_(hf), shading_(shading) {
  if (hf.width < 2 || hf.height < 2 || !hf.has_samples())
    throw std::invalid_argument(hf.source + ": " + std::to_string(hf.width) + "x" + std::to_string(hf.height) +
                                " samples: a terrain needs at least 2 x 2 samples to form a surface");
  const int max_size = gl::max_texture_size();
  set_sun_direction(shading_.sun_direction.value_or(ShadingParams::kDefaultSunDirection));
  if (const auto refused = set_clouds(shading.clouds); !refused.empty())
    throw std::invalid_argument("environment.clouds: " + refused.front());

  const auto t0 = std::chrono::steady_clock::now();
  const int limit = texture_limit > 0 ? std::min(texture_limit, int(max_size)) : int(max_size);
  texture_limit_ = limit;
  if (hf.width > limit || hf.height > limit || hf.paged) {
    // Beyond one texture (or the memory budget: paged heights): an overview
    // for the whole DEM, full resolution in a window.
    overview_step_ = terrain::overview_step_for(hf.width, hf.height, std::min(kOverviewSide, limit));
    if (hf.paged && hf.paged->overview_step == overview_step_)
      overview_ = std::make_unique<terrain::Heightfield>(*hf.paged->overview);  // built at load
    else
      overview_ = std::make_unique<terrain::Heightfield>(terrain::decimate_heightfield(hf, overview_step_));
    int window = std::min(kDefaultHeightWindow, limit);
    if (hf.paged) {  // window + one tile around it in at most half the budget
      const auto& cache = *hf.paged->cache;
      const int fit = int(std::sqrt(double(cache.budget_bytes()) / 2.0 / sizeof(float))) - 2 * cache.tile_size();
      window = std::min(window, std::max(fit, kMinPagedHeightWindow));
    }
    windows_[0].height = std::make_unique<HeightWindowTexture>(hf, window);
  }
  const terrain::Heightfield& tex = texture_heightfield();
  height_tex_ = gl::upload_height_texture(tex.width, tex.height, tex.heights.data());
  if (!overview_ && (long long)tex.width * tex.height <= kMaxHeightDifferencesSamples)
    height_differences_tex_ = gl::upload_height_differences_texture(tex.width, tex.height, tex.heights.data());
  if (shading_.ground_detail) detail_tex_ = upload_detail_texture();
  if (hf.water && !hf.water->empty()) {
    const water::ShoreGrid grid = water::shore_grid(*hf.water, overview_step_);
    water::PresenceBuilder presence_builder(grid);
    water_share_tex_ = upload_water_share(*hf.water, overview_step_, presence_builder);
    water_share_size_ = glm::ivec2(grid.width, grid.height);
    const water::WaveSlopes waves = water::make_wave_slopes();
    waves_tex_ = gl::upload_wave_texture(waves.size, waves.rgba.data());
    const std::vector<water::PresenceLevel> presence = presence_builder.levels();
    std::vector<gl::PresenceTexels> levels;
    for (const auto& l : presence) levels.push_back({l.width, l.height, l.texels.data()});
    water_presence_tex_ = gl::upload_water_presence_texture(levels);
  }
  gl::finish();  // so upload_ms is the real transfer, not just the enqueue
  upload_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  pyramid_ = std::make_unique<terrain::HeightPyramid>(hf);

  if (imagery_path) {
    // Georeferenced imagery is warped onto the DEM's footprint (terrain/imagery_loader.h).
    terrain::Imagery img;
    terrain::ImageryPaging paging;  // beyond the limit: paged for a window of this side
    paging.window_side = std::min(kDefaultHeightWindow, limit);
    if (imagery_budget_bytes > 0) paging.budget_bytes = imagery_budget_bytes;
    try {
      img = terrain::load_imagery(hf, *imagery_path, limit, paging);
    } catch (const std::exception& e) {
      throw gl::GlError(e.what());
    }
    imagery_tex_ = gl::upload_colour_texture(img.width, img.height, img.rgb.data(), /*rgba=*/false, /*repeat=*/false);
    imagery_uncovered_ = img.uncovered;
    imagery_overview_step_ = img.full_step;
    // The overview spans whole blocks, a little more than the footprint
    // (1 exactly for imagery that fits).
    const glm::ivec2 overview_span = glm::ivec2(img.width, img.height) * img.full_step;
    imagery_overview_scale_ = glm::vec2(img.full_width(), img.full_height()) / glm::vec2(overview_span);
    if (img.paged) {  // finer than one texture: full resolution in a window (one per set)
      imagery_window_side_ = paging.window_side;
      windows_[0].imagery = std::make_unique<ImageryWindowTexture>(img, hf.width, hf.height, imagery_window_side_,
                                                               *imagery_path + ": imagery window");
      img.rgb = {};
      window_imagery_ = std::make_unique<terrain::Imagery>(std::move(img));
    }
  }
}

const char* TerrainScene::height_at_stage() const {
  const bool whole_heights = !overview_ && !windows_[0].height;
  linked_without_window_ = linked_without_window_ || whole_heights;
  return whole_heights ? "height_at_whole.frag" : "height_at_window.frag";
}

std::vector<std::string> TerrainScene::shading_library(bool with_water) const {
  std::vector<std::string> stages = {"terrain_shading.frag",
          "fog.frag",
          shading_.ground_detail ? "ground_detail.frag" : "ground_plain.frag",
          height_differences_texture() ? "height_differences_texture.frag" : "height_differences_heights.frag",
          height_at_stage(),
          has_imagery() ? "imagery.frag" : "imagery_none.frag"};
  if (with_water) {
    stages.insert(stages.end(), {"water_in_shading.frag", "water.frag", "sky_colour.frag"});
  } else {
    stages.push_back("water_none.frag");
  }
  return stages;
}

std::vector<std::string> TerrainScene::shading_stages(const std::vector<std::string>& own) const {
  // Deferred shading draws the water in a pass of its own.
  std::vector<std::string> stages = shading_library(has_water() && !shading_.deferred_shading);
  stages.push_back(shading_.deferred_shading ? "shade_deferred.frag" : "shade_forward.frag");
  stages.insert(stages.end(), own.begin(), own.end());
  return stages;
}

std::vector<std::string> TerrainScene::deferred_shade_stages() const {
  std::vector<std::string> stages = shading_library(false);
  stages.push_back("deferred_shade.frag");
  // With water it also marks where water may be, for the water pass.
  if (has_water()) {
    stages.insert(stages.end(), {"water_mark.frag", "water.frag", "sky_colour.frag"});
  } else {
    stages.push_back("water_mark_none.frag");
  }
  return stages;
}

std::vector<std::string> TerrainScene::water_mask_stages() const {
  if (!has_water()) return {};
  return {"water_mask.frag"};
}

std::vector<std::string> TerrainScene::water_shade_stages() const {
  if (!has_water()) return {};
  return {"water_shade.frag", "water.frag", "sky_colour.frag", "fog.frag", height_at_stage()};
}

void TerrainScene::set_ground_detail(bool on) {
  shading_.ground_detail = on;
  if (on && !detail_tex_) detail_tex_ = upload_detail_texture();
}

Camera TerrainScene::local_camera(const Camera& world) const {
  Camera c = world;
  c.position = world.position - world_origin_;
  c.earth_radius_m = earth_radius_m_;
  return c;
}

void TerrainScene::bind_common(const gl::ShaderProgram& p, const Camera& camera, int windows) const {
  const HeightWindowTexture* height_window = windows >= 0 ? windows_[windows].height.get() : nullptr;
  const ImageryWindowTexture* imagery_window = windows >= 0 ? windows_[windows].imagery.get() : nullptr;
  using gl::TextureUnit;
  gl::bind_texture(TextureUnit::kHeight, height_tex_);
  p.set("u_height", gl::unit(TextureUnit::kHeight));
  if (height_differences_tex_ && p.location("u_height_differences") >= 0) {
    gl::bind_texture(TextureUnit::kHeightDifferences, height_differences_tex_);
    p.set("u_height_differences", gl::unit(TextureUnit::kHeightDifferences));
  }
  p.set("u_has_imagery", has_imagery() ? 1 : 0);
  if (has_imagery()) {
    gl::bind_texture(TextureUnit::kImagery, imagery_tex_);
    p.set("u_imagery", gl::unit(TextureUnit::kImagery));
    p.set("u_imagery_overview_scale", imagery_overview_scale_);
  }
  const bool windowed = height_window && height_window->placed();
  if (windowed) {
    gl::bind_texture(TextureUnit::kHeightWindow, height_window->id());
    p.set("u_height_window", gl::unit(TextureUnit::kHeightWindow));
  }
  p.set("u_window_origin", windowed ? height_window->origin() : glm::ivec2(0));
  p.set("u_window_size", windowed ? height_window->size() : glm::ivec2(0));
  p.set("u_overview_step", overview_step_);
  const bool imagery_windowed = imagery_window && imagery_window->placed();
  if (imagery_windowed) {
    gl::bind_texture(TextureUnit::kImageryWindow, imagery_window->id());
    p.set("u_imagery_window", gl::unit(TextureUnit::kImageryWindow));
    p.set("u_imagery_full_size", imagery_window->full_size());
    p.set("u_imagery_overview_lod", std::log2(float(imagery_overview_step_)));
  }
  p.set("u_imagery_window_origin", imagery_windowed ? imagery_window->origin() : glm::ivec2(0));
  p.set("u_imagery_window_size", imagery_windowed ? imagery_window->size() : glm::ivec2(0));
  // Beyond one texture, sample coordinates reach 2^14 and more: interpolated
  // across Level0's large triangles they lose up to a few hundredths of a
  // sample in float, enough for Level0's clip test against Level1's square to
  // drop fragments just outside it (single sky pixels, docs/results.md). So
  // the test is relaxed by a tenth of a sample there; 0 (unchanged images)
  // for DEMs that fit.
  p.set("u_clip_margin", overview_step_ > 1 ? 0.1f : 0.0f);
  p.set("u_dem_size", glm::ivec2(heightfield_.width, heightfield_.height));
  p.set("u_spacing", glm::vec2(float(heightfield_.spacing_x_m), float(heightfield_.spacing_y_m)));
  p.set("u_height_range", glm::vec2(heightfield_.min_m, heightfield_.max_m));
  p.set("u_sun_dir", sky_light_.light_direction);
  p.set("u_light_color", sky_light_.light_colour);
  p.set("u_ambient", sky_light_.ambient);
  // Ground detail (programs linked with ground_detail.frag): the
  // tiles' phase at a whole sample near the eye, in double (a float product
  // of a large sample index would lose it).
  if (detail_tex_ && p.location("u_detail") >= 0) {
    gl::bind_texture(TextureUnit::kGroundDetail, detail_tex_);
    p.set("u_detail", gl::unit(TextureUnit::kGroundDetail));
    const glm::dvec2 spacing(heightfield_.spacing_x_m, heightfield_.spacing_y_m);
    const glm::dvec2 anchor = glm::floor(glm::dvec2(camera.position) / spacing);
    p.set("u_detail_anchor", glm::vec2(anchor));
    static const char* const kTileNames[3] = {"u_detail_tile_m[0]", "u_detail_tile_m[1]", "u_detail_tile_m[2]"};
    static const char* const kPhaseNames[3] = {"u_detail_phase[0]", "u_detail_phase[1]", "u_detail_phase[2]"};
    for (int k = 0; k < 3; ++k) {
      p.set(kTileNames[k], kDetailTileM[k]);
      p.set(kPhaseNames[k], glm::vec2(terrain::detail_tile_phase(anchor, spacing, kDetailTileM[k])));
    }
  }
  if (has_water() && (p.location("u_water_share") >= 0 || p.location("u_water_presence") >= 0)) bind_water(p, camera);
  p.set("u_fog_color", sky_light_.sky_horizon);
  p.set("u_fog_k", float(fog_k()));
  p.set("u_view_proj", camera.view_projection());
  p.set("u_earth_radius_m", float(camera.earth_radius_m));
  p.set("u_alpha", gl::coverage::kLevel1);
}

double TerrainScene::fog_k() const {
  // Fog reaches 98 % at the visibility distance: exp(-(k V)^2) = 0.02.
  return shading_.fog_visibility_m > 0 ? std::sqrt(std::log(50.0)) / shading_.fog_visibility_m : 0.0;
}

void TerrainScene::bind_water(const gl::ShaderProgram& p, const Camera& camera) const {
  using gl::TextureUnit;
  gl::bind_texture(TextureUnit::kWaterShare, water_share_tex_);
  p.set("u_water_share", gl::unit(TextureUnit::kWaterShare));
  p.set("u_water_share_size", glm::vec2(water_share_size_));
  p.set("u_water_step", float(overview_step_));
  gl::bind_texture(TextureUnit::kWaves, waves_tex_);
  p.set("u_waves", gl::unit(TextureUnit::kWaves));
  gl::bind_texture(TextureUnit::kWaterPresence, water_presence_tex_);
  p.set("u_water_presence", gl::unit(TextureUnit::kWaterPresence));
  p.set("u_water_presence_block", float(water::kPresenceBlock));
  // The eye and the waves' phases about a whole sample near it, in double:
  // exact however far the terrain reaches.
  const glm::dvec2 spacing(heightfield_.spacing_x_m, heightfield_.spacing_y_m);
  const glm::dvec2 anchor = glm::floor(glm::dvec2(camera.position) / spacing);
  p.set("u_water_anchor", glm::vec2(anchor));
  p.set("u_water_eye", glm::vec3(glm::dvec3(glm::dvec2(camera.position) - anchor * spacing, camera.position.z)));
  static const char* const kTileNames[water::kWaveLayers] = {"u_wave_tile_m[0]", "u_wave_tile_m[1]"};
  static const char* const kPhaseNames[water::kWaveLayers] = {"u_wave_phase[0]", "u_wave_phase[1]"};
  for (int k = 0; k < water::kWaveLayers; ++k) {
    p.set(kTileNames[k], float(water::wave_layer(k).tile_m));
    p.set(kPhaseNames[k], glm::vec2(water::wave_phase(anchor, spacing, k, time_s_)));
  }
  p.set("u_wave_unresolved", float(water::kUnresolvedSlopeVariance));
  p.set("u_wave_variance", float(water::kSeaSlopeVariance));
  p.set("u_sun_light", sky_light_.sun_light);
  gl::set_sky_colours(p, sky_light_);
}

void TerrainScene::set_sun_direction(const glm::vec3& towards_sun) {
  sky_light_ = environment::sky_light_for(towards_sun, shading_);
}

void TerrainScene::enable_height_window(int size) {
  auto& first = windows_[0].height;
  if (size <= 0 && overview_) size = first ? first->size().x : kDefaultHeightWindow;
  if (size > 0 && linked_without_window_)
    throw std::logic_error("enable_height_window after a shading program was linked without the window's reads");
  for (Windows& set : windows_)
    set.height = size > 0 ? std::make_unique<HeightWindowTexture>(heightfield_, size) : nullptr;
}

int TerrainScene::claim_windows() {
  for (std::size_t k = 0; k < windows_in_use_.size(); ++k)
    if (!windows_in_use_[k]) {
      windows_in_use_[k] = true;
      return int(k);
    }
  Windows set;  // a new set like the first
  if (const auto& h = windows_[0].height) set.height = std::make_unique<HeightWindowTexture>(heightfield_, h->size().x);
  if (window_imagery_)  // the same paged imagery (one tile cache), its own window
    set.imagery = std::make_unique<ImageryWindowTexture>(*window_imagery_, heightfield_.width, heightfield_.height,
                                                         imagery_window_side_, heightfield_.source + ": imagery window");
  windows_.push_back(std::move(set));
  windows_in_use_.push_back(true);
  return int(windows_.size()) - 1;
}

void TerrainScene::release_windows(int set) {
  if (set >= 0 && set < int(windows_in_use_.size())) windows_in_use_[set] = false;
}

void TerrainScene::place_imagery_window(glm::ivec2 centre) {
  for (const Windows& set : windows_)
    if (set.imagery) {
      set.imagery->centre_on_sample(centre, /*wait=*/true);
      set.imagery->cache().wait_idle();
    }
}

void TerrainScene::prefetch_heights(const std::vector<glm::dvec3>& points_m) {
  if (!heightfield_.paged) return;
  const terrain::HeightTileCache& cache = *heightfield_.paged->cache;
  const int half = cache.tile_size() / 2;
  for (const glm::dvec3& p : points_m) {
    const int i = int(p.x / heightfield_.spacing_x_m), j = int(p.y / heightfield_.spacing_y_m);
    cache.request(i - half, j - half, 2 * half + 1, 2 * half + 1);
  }
}

void TerrainScene::prefetch_samples(glm::ivec2 lo, glm::ivec2 hi) {
  if (!heightfield_.paged) return;
  const terrain::HeightTileCache& cache = *heightfield_.paged->cache;
  const int t = cache.tile_size();
  cache.request(lo.x - t, lo.y - t, hi.x - lo.x + 1 + 2 * t, hi.y - lo.y + 1 + 2 * t);
}

void TerrainScene::apply(const lod::SceneRequests& requests) {
  for (const auto& [lo, hi] : requests.sample_rects) prefetch_samples(lo, hi);
  if (!requests.points_m.empty()) prefetch_heights(requests.points_m);
  if (requests.window_set >= 0) follow_window(requests.window_set, requests.window_centre);
  const auto& [lo, hi] = requests.square_and_band;
  if (lo.x <= hi.x && lo.y <= hi.y) prefetch_samples(lo, hi);
}

bool TerrainScene::samples_resident(glm::ivec2 lo, glm::ivec2 hi) const {
  if (!heightfield_.paged) return true;
  return heightfield_.paged->cache->resident_rect(lo.x, lo.y, hi.x - lo.x + 1, hi.y - lo.y + 1);
}

std::optional<std::pair<glm::ivec2, glm::ivec2>> TerrainScene::window_samples(int set, glm::ivec2 centre) const {
  const HeightWindowTexture* window = windows_[set].height.get();
  if (!window || !heightfield_.paged) return std::nullopt;
  const glm::ivec2 o = window->origin_for(centre), s = window->size();
  return std::pair{o, o + s - 1};
}

long long TerrainScene::follow_window(int set, glm::ivec2 centre) {
  const Windows& w = windows_[set];
  if (w.imagery) w.imagery->centre_on_sample(centre, wait_for_pages_);  // live: held until its tiles are in
  return w.height ? w.height->centre_on(centre) : 0;
}

std::vector<std::string> TerrainScene::set_clouds(const options::CloudLayers& layers) {
  std::vector<std::string> refused;
  options::CloudLayers kept;
  for (const auto& l : layers) {
    auto check = environment::check_cloud_layer(l, heightfield_.min_m);
    if (check.layer && int(kept.size()) == environment::kMaxCloudLayers)
      check = {std::nullopt, "more than " + std::to_string(environment::kMaxCloudLayers) + " cloud layers"};
    if (check.layer) kept.push_back(*check.layer);
    else refused.push_back("cloud layer " + std::to_string(l.id) + ": " + check.refused);
  }
  shading_.clouds = std::move(kept);
  return refused;
}

}  // namespace ig::render
