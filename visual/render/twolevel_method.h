#pragma once
// The two-level terrain method (docs/twolevel.md):
//   Level0: a static, view-independent ROAM mesh over the whole DEM.
//   Level1: a full-resolution grid of N x N samples centred on E (where the
//           view's centre ray meets the terrain), snapped to whole samples.
// Passes: level1 (colour + depth into the frame, alpha 1), band (Level1's
// grid grown by w_trans into an RGBA16F target: uv, beta, mask), level0
// (clipped to outside the Level1 square, depth-tested against Level1, band
// pixels shaded with the blended coordinate), then a coverage count whose
// result steers next frame's Level1 size.

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gl/gl_objects.h"
#include "gl/shader_program.h"
#include "lod/level0_clusters.h"
#include "lod/level0_height_query.h"
#include "lod/level1_size_controller.h"
#include "lod/look_at_point.h"
#include "lod/roam_level0_mesh.h"
#include "options/twolevel_options.h"
#include "gl/grid_mesh.h"
#include "render/terrain_method.h"
#include "terrain/height_pyramid.h"

namespace ig::render {

using options::TwoLevelOptions;  // options/twolevel_options.h

class TwoLevelMethod final : public TerrainMethod {
 public:
  TwoLevelMethod(const TerrainScene& scene, const std::string& shader_dir, TwoLevelOptions options = {});
  ~TwoLevelMethod() override;
  std::string name() const override { return "twolevel"; }
  std::vector<std::string> column_names() const override;
  std::vector<std::string> pass_names() const override;
  void update(const Camera& camera) override;
  void set_viewport(int width_px, int height_px) override { viewport_ = {width_px, height_px}; }
  MethodFrameStats draw(const Camera& camera, const gl::RenderTarget& target) override;
  std::optional<ErrorKnob> knob() const override {
    return ErrorKnob{"level0_budget", "triangles", double(options_.level0_budget)};
  }
  // Level1 is exact; Level0's error (max_error_m) seen from the nearest point
  // where Level0 is drawn: the edge of the Level1 square when the eye is over
  // it, else the ground under the eye.
  std::optional<double> error_bound_px(const Camera& camera, int viewport_height_px) const override;

  // State of the last update, for tests and logs.
  // This frame's Level1 size: the controller's, or larger under the eye guard.
  int level1_size() const { return n_ > 0 ? n_ : controller_.size(); }
  const lod::LookAtPoint& look_at() const { return look_at_; }
  glm::ivec2 level1_origin() const { return origin_; }
  double last_ratio() const { return last_ratio_; }
  bool eye_guarded() const { return eye_guarded_; }  // this frame's Level1 size / centre came from the eye guard
  // Paged heights: this frame's Level1 is last frame's, the new one's heights not being resident yet.
  bool level1_held() const { return level1_held_; }
  // Level0's largest error, seen from the nearest point the largest Level1
  // square around E could reach, is under kFarLevel0ErrorPx pixels: Level1
  // took its smallest size (E far out).
  bool level1_far() const { return far_; }
  static constexpr double kFarLevel0ErrorPx = 0.5;
  const terrain::HeightPyramid& pyramid() const { return pyramid_; }
  const lod::Level0Mesh& level0() const { return level0_; }
  // Level0's drawn height at a sample position (the walls use it; so do "as drawn" host answers).
  const lod::Level0HeightQuery& level0_heights() const { return level0_heights_; }
  int band_width_samples() const { return band_w_; }
  // Level0 clusters and Level1 blocks in view but hidden behind nearer terrain this frame (not drawn).
  int level0_hidden_clusters() const { return level0_hidden_clusters_; }
  int level1_hidden_blocks() const { return level1_hidden_blocks_; }
  void set_thresholds(double a1, double a2) { controller_.set_thresholds(a1, a2); }
  // The generic controls (twolevel_method_controls.cpp).
  void tune(const MethodTuning& tuning) override;
  std::optional<LevelStatus> level_status() const override;
  std::optional<double> coarse_height_at(double i, double j) const override;

 private:
  struct SizeMeshes;  // wall and band ring for one Level1 size, built on first use
  SizeMeshes& meshes_for(int n, int band_w);
  void ensure_band_target(int width, int height);
  void upload_beta_template(int n, int band_w);
  void update_walls(SizeMeshes& meshes, int n);
  double read_previous_ratio();
  // Sets look_at_, far_, n_, origin_, eye_guarded_ for this frame; false when
  // Level1 keeps last frame's square because paged heights it needs are not
  // resident yet (see the .cpp).
  bool place_level1(const Camera& camera, double ratio, const glm::dvec2& eye);

  const TerrainScene& scene_;
  int windows_ = -1;  // the scene's window set this method keeps on its Level1 (TerrainScene::claim_windows)
  TwoLevelOptions options_;
  gl::ShaderProgram grid_program_, level0_program_, level0_clipped_program_, band_program_;
  // The coverage count, for a single-sampled or a multisampled frame
  // (made for the first frame's kind, again if the kind changes).
  std::string shader_dir_;
  gl::ShaderProgram count_program_;
  bool count_multisampled_ = false;
  const terrain::HeightPyramid& pyramid_;  // the scene's, shared across channels
  glm::ivec2 viewport_{640, 480};
  std::vector<glm::dvec3> prediction_rays_;
  lod::Level0Mesh level0_;
  lod::Level0HeightQuery level0_heights_;
  gl::VertexArray level0_vao_;
  gl::Buffer level0_vbo_, level0_ibo_;
  // Level0's static buffer as culled clusters; this frame's runs of it:
  // [0] wholly outside the Level1 square, [1] across its edge.
  std::unique_ptr<lod::Level0Clusters> level0_clusters_;
  std::unique_ptr<lod::HorizonCulling> horizon_;  // null when options_.horizon_culling is off
  int level0_hidden_clusters_ = 0;  // Level0 clusters and Level1 blocks hidden behind nearer terrain this frame
  int level1_hidden_blocks_ = 0;
  std::array<lod::IndexRuns, 2> level0_runs_;
  std::array<std::vector<GLsizei>, 2> draw_counts_;       // the runs as glMultiDrawElements takes them
  std::array<std::vector<const void*>, 2> draw_offsets_;  // (filled in update())
  gl::GridMesh block_mesh_;  // 32 x 32 quads: Level1 is drawn as culled blocks of it
  std::map<std::pair<int, int>, std::unique_ptr<SizeMeshes>> size_meshes_;
  lod::Level1SizeController controller_;

  // Per-frame selection (update()).
  lod::LookAtPoint look_at_;
  glm::ivec2 origin_{0};
  int band_w_ = 0;
  double last_ratio_ = -1.0;
  bool eye_guarded_ = false;
  int n_ = 0;  // Level1 vertices a side used this frame (0 before the first)
  bool level1_held_ = false;  // this frame kept last frame's square (paged heights not in yet)
  bool far_ = false;  // Level0's error at E under kFarLevel0ErrorPx: Level1 at its smallest
  // (eye guard, band width, blocks: lod/level1_selection.h)
  bool terrain_visible_ = false, band_visible_ = false;
  glm::ivec4 band_rect_{0};  // the band's screen rectangle (x0, y0, x1, y1), from update()
  std::vector<glm::ivec2> visible_blocks_;

  // Band target (RGBA16F + depth), beta template, coverage queries.
  std::unique_ptr<gl::RenderTarget> band_target_;
  gl::Texture beta_tex_;
  std::pair<int, int> beta_for_{0, 0};
  gl::Framebuffer count_fbo_;
  gl::VertexArray empty_vao_;
  gl::Query queries_[2][2];  // [frame parity][level1, terrain] samples passed
  bool query_pending_[2] = {false, false};
  int parity_ = 0;
  double level0_resolution_ = 0.0;  // r0 = Level0 vertices / DEM samples
};

}  // namespace ig::render
