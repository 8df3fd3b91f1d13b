#pragma once
// The cloud layers (shaders/clouds.frag, environment/cloud_frame.h), after
// the sky, over whatever the frame holds (sky, terrain, water, entities):
// marched at half the frame's resolution into a target of the pass's own,
// reading the frame's depth to stop each ray at the terrain, then blended
// over the frame by a depth-aware upsample (shaders/clouds_upsample.frag).
// The march is the cost, so a quarter of the pixels march. Made only for a
// frame that has clouds: a scene without them links no cloud shader and
// allocates no texture.

#include <string>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include "environment/cloud_frame.h"
#include "gl/gl_objects.h"
#include "gl/render_target.h"
#include "gl/shader_program.h"
#include "gl/work_counters.h"

namespace ig::gl {

struct CloudView {
  glm::mat4 inv_view_proj{1.0f};  // clip -> eye-relative world
  float eye_altitude_m = 0.0f;    // above sea level
  double earth_radius_m = 0.0;    // 0: a flat world
  double fov_y_deg = 60.0;
  float fog_k = 0.0f;             // the terrain's fog (fog.frag's k) and colour
  glm::vec3 fog_colour{0.0f};
};

class CloudPass {
 public:
  explicit CloudPass(const std::string& shader_dir);
  // Blends the layers over the target's picture as drawn so far (after the
  // sky; multisampled targets after their resolve), recorded as pass "clouds".
  void draw(const environment::CloudFrame& clouds, const CloudView& view, const RenderTarget& target,
            PassRecorder& recorder);

 private:
  void make_half_target(int width, int height);
  ShaderProgram march_, upsample_;
  Texture noise_;
  VertexArray empty_vao_;
  // The half-resolution target, for frames of frame_size_.
  glm::ivec2 frame_size_{0};
  Texture light_, depth_;
  Framebuffer half_;
};

}  // namespace ig::gl
