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
// The frame's CPU step is lod::TwoLevelSelector (lod/twolevel_selection.h:
// a TwoLevelSelection value), the passes are gl::TwoLevelPasses
// (gl/twolevel_passes.h); this class joins them to the scene: the view and
// paging state in, the selection's scene requests (tiles, the height
// window's centre) applied to the scene, the scene's textures bound.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gl/twolevel_passes.h"
#include "lod/twolevel_selection.h"
#include "options/twolevel_options.h"
#include "gl/grid_mesh.h"
#include "render/terrain_method.h"
#include "terrain/height_pyramid.h"

namespace ig::render {

using options::TwoLevelOptions;  // options/twolevel_options.h

class TwoLevelMethod final : public TerrainMethod {
 public:
  TwoLevelMethod(TerrainScene& scene, const std::string& shader_dir, TwoLevelOptions options = {});
  ~TwoLevelMethod() override;
  std::string name() const override { return "twolevel"; }
  std::vector<std::string> column_names() const override;
  std::vector<std::string> pass_names() const override;
  int window_set() const override { return windows_; }
  lod::SceneRequests update(const Camera& camera) override;
  void set_viewport(int width_px, int height_px) override { viewport_ = {width_px, height_px}; }
  MethodFrameStats draw(const Camera& camera, const gl::RenderTarget& target) override;
  std::optional<ErrorKnob> knob() const override {
    return ErrorKnob{"level0_budget", "triangles", double(options_.level0_budget)};
  }
  // Level1 is exact; Level0's error (max_error_m) seen from the nearest point
  // where Level0 is drawn: the edge of the Level1 square when the eye is over
  // it, else the ground under the eye.
  std::optional<double> error_bound_px(const Camera& camera, int viewport_height_px) const override;

  // The last update's selection (lod/twolevel_selection.h), for tests and logs.
  const lod::TwoLevelSelection& selection() const { return selector_->last(); }
  // This frame's Level1 size: the controller's, or larger under the eye guard.
  int level1_size() const { return selector_->level1_size(); }
  const lod::LookAtPoint& look_at() const { return selection().look_at; }
  glm::ivec2 level1_origin() const { return selection().origin; }
  double last_ratio() const { return selection().last_ratio; }
  bool eye_guarded() const { return selection().eye_guarded; }  // this frame's Level1 size / centre came from the eye guard
  // Paged heights: this frame's Level1 is last frame's, the new one's heights not being resident yet.
  bool level1_held() const { return selection().held; }
  // Level0's largest error, seen from the nearest point the largest Level1
  // square around E could reach, is under kFarLevel0ErrorPx pixels: Level1
  // took its smallest size (E far out).
  bool level1_far() const { return selection().far; }
  static constexpr double kFarLevel0ErrorPx = lod::TwoLevelSelector::kFarLevel0ErrorPx;
  const terrain::HeightPyramid& pyramid() const { return pyramid_; }
  const lod::Level0Mesh& level0() const { return selector_->level0(); }
  // Level0's drawn height at a sample position (the walls use it; so do "as drawn" host answers).
  const lod::Level0HeightQuery& level0_heights() const { return selector_->level0_heights(); }
  int band_width_samples() const { return selection().band_w; }
  // Level0 clusters and Level1 blocks in view but hidden behind nearer terrain this frame (not drawn).
  int level0_hidden_clusters() const { return selection().level0_hidden_clusters; }
  int level1_hidden_blocks() const { return selection().level1_hidden_blocks; }
  void set_thresholds(double a1, double a2) { selector_->set_thresholds(a1, a2); }
  // For tests: all of Level0 outside the square through the band's program.
  void set_band_split(bool on) { selector_->set_band_split(on); }
  // The generic controls (twolevel_method_controls.cpp).
  void tune(const MethodTuning& tuning) override;
  std::optional<LevelStatus> level_status() const override;
  std::optional<double> coarse_height_at(double i, double j) const override;

 private:
  // The scene's side of the frame: tiles the selection asks for, the
  // height window on Level1.

  TerrainScene& scene_;  // its windows follow Level1; tiles are asked for
  int windows_ = -1;  // the scene's window set this method keeps on its Level1 (TerrainScene::claim_windows)
  TwoLevelOptions options_;
  const terrain::HeightPyramid& pyramid_;  // the scene's, shared across channels
  glm::ivec2 viewport_{640, 480};
  std::unique_ptr<lod::TwoLevelSelector> selector_;
  std::unique_ptr<gl::TwoLevelPasses> passes_;
  gl::GridMesh block_mesh_;  // kLevel1BlockQuads a side: Level1 is drawn as culled blocks of it
};

}  // namespace ig::render
