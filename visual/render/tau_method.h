#pragma once
// What the chunked and GeoMipMapping methods share: a precomputed set of
// grid pieces chosen per frame by their projected error against tau_px (the
// knob, pixels at the viewport's height), drawn one piece at a time with one
// program placed by its origin sample, eye-relative in double then float.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gl/shader_program.h"
#include "gl/uniform.h"
#include "lod/drawn_surface_occlusion.h"
#include "render/terrain_method.h"

namespace ig::render {

class TauMethod : public TerrainMethod {
 public:
  void set_viewport(int width_px, int height_px) override;
  std::optional<ErrorKnob> knob() const override { return ErrorKnob{"tau_px", "px", tau_px_}; }

 protected:
  // Throws std::invalid_argument "<name>: tau_px must be ..." unless tau_px
  // is positive and finite.
  TauMethod(const std::string& name, const TerrainScene& scene, const std::string& shader_dir,
            const std::string& vertex_shader, double tau_px, bool horizon_culling);

  // Horizon culling over this frame's drawn pieces (lod/drawn_surface_occlusion.h
  // remove_hidden: box_of and span_of per piece); hidden_boxes() counts
  // what it removed. Nothing when off.
  template <class Piece, class BoxOf, class SpanOf>
  void remove_hidden(const Camera& camera, std::vector<Piece>& pieces, BoxOf box_of, SpanOf span_of) {
    hidden_boxes_ = occlusion_ ? occlusion_->remove_hidden(camera.position, camera.earth_radius_m,
                                                           10.0 * camera.near_m, pieces, box_of, span_of)
                               : 0;
  }
  int hidden_boxes() const { return hidden_boxes_; }

  // Pixels per radian for the viewport of the next update.
  double viewport_pixels_per_radian(const Camera& camera) const { return pixels_per_radian(camera, viewport_h_); }

  // The program in use with the scene's common uniforms; place() then puts
  // the next piece at origin sample (i0, j0).
  struct Placement {
    gl::Uniform origin, origin_rel;
  };
  Placement begin_draw(const Camera& camera) const;
  void place(const Placement& p, const Camera& camera, int i0, int j0) const;

  const TerrainScene& scene_;
  double tau_px_;
  gl::ShaderProgram program_;

 private:
  int viewport_h_ = 1024;  // until the first set_viewport()
  std::unique_ptr<lod::DrawnSurfaceOcclusion> occlusion_;  // null: horizon culling off
  int hidden_boxes_ = 0;
};

}  // namespace ig::render
