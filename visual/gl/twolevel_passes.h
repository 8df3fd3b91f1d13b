#pragma once
// The two-level method's passes (docs/twolevel.md), drawing a
// lod::TwoLevelSelection: level1 (blocks and walls into the frame, coverage
// code kLevel1), band (the grown grid into its own RGBA16F target: uv, beta,
// mask), level0 (outside the Level1 square, depth-tested, band pixels
// shaded with the blended coordinate; code kLevel0), then the coverage count
// whose result (read a frame later, never waiting) steers the next size.

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "gl/gl_objects.h"
#include "gl/render_target.h"
#include "gl/shader_program.h"
#include "gl/twolevel_meshes.h"
#include "lod/twolevel_selection.h"
#include "options/twolevel_options.h"

namespace ig::gl {

// The fragment stages of each terrain program (the scene's shading around
// the method's own mains).
struct TwoLevelStages {
  // level0_without_band: for Level0 the band cannot reach (lod::TwoLevelSelection::level0_runs[2]).
  std::vector<std::string> grid, level0, level0_clipped, level0_without_band;
};

// What a frame's draw needs besides the selection.
struct TwoLevelDrawContext {
  glm::dvec3 eye{0.0};  // terrain-local metres
  double near_m = 0.5, far_m = 300000.0;
  glm::dvec2 spacing{1.0};  // DEM sample spacing, metres
  std::function<void(const ShaderProgram&)> bind_common;  // the scene's textures and uniforms
  // The work counters' pass (count_samples false: the pass runs its own samples-passed queries).
  std::function<void(std::string_view, bool count_samples)> begin_pass;
  std::function<void()> draw_block;                       // one Level1 block (kLevel1BlockQuads a side)
};

struct TwoLevelDrawn {
  long long level1_tris = 0, band_tris = 0, level0_tris = 0;
  std::vector<std::string> passes;  // those that ran
};

class TwoLevelPasses {
 public:
  TwoLevelPasses(const std::string& shader_dir, const TwoLevelStages& stages, const lod::Level0Mesh& level0,
                 const std::vector<float>& lift, const options::TwoLevelOptions& options);
  // Last frame's coverage ratio R = Level1 / terrain samples; -1 when the
  // driver has not finished it (the size is then kept a frame).
  double read_previous_ratio();
  TwoLevelDrawn draw(const lod::TwoLevelSelection& sel, const TwoLevelDrawContext& ctx, const RenderTarget& target);

 private:
  Level1SizeMeshes& meshes_for(int n, int band_w);
  bool skipped(const char* pass) const;
  void draw_level1(const lod::TwoLevelSelection& sel, const TwoLevelDrawContext& ctx, TwoLevelDrawn& drawn);
  bool draw_band(const lod::TwoLevelSelection& sel, const TwoLevelDrawContext& ctx, const RenderTarget& target,
                 TwoLevelDrawn& drawn);
  void draw_level0(const lod::TwoLevelSelection& sel, const TwoLevelDrawContext& ctx, const RenderTarget& target,
                   bool band_on, TwoLevelDrawn& drawn);
  void count(const RenderTarget& target);

  options::TwoLevelOptions options_;
  std::string shader_dir_;
  ShaderProgram grid_program_, level0_program_, level0_clipped_program_, level0_without_band_program_, band_program_;
  // The coverage count, for a single-sampled or a multisampled frame (made
  // for the first frame's kind, again if the kind changes).
  ShaderProgram count_program_;
  bool count_multisampled_ = false;
  Level0Buffer level0_;
  double level0_max_error_m_ = 0.0;  // sets the band's depth tolerance (lod::BandRing::tolerance_for)
  // The meshes of the last two (N, w) pairs drawn: enough for a size that
  // steps back and forth, while a flight through many sizes keeps no more
  // (the ring at N = 1025 alone is megabytes).
  struct SizedMeshes {
    std::pair<int, int> key;
    std::unique_ptr<Level1SizeMeshes> meshes;
  };
  std::vector<SizedMeshes> size_meshes_;  // most recently used first
  std::unique_ptr<RenderTarget> band_target_;
  BetaTemplate beta_;
  // The level0 runs as glMultiDrawElements takes them (counts, byte offsets).
  std::vector<GLsizei> draw_counts_;
  std::vector<const void*> draw_offsets_;
  Framebuffer count_fbo_;  // no attachments
  VertexArray empty_vao_;
  Query queries_[2][2];  // [frame parity][level1, terrain] samples passed
  bool query_pending_[2] = {false, false};
  int parity_ = 0;
};

}  // namespace ig::gl
