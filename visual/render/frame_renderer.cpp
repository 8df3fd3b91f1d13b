#include "render/frame_renderer.h"

#include <chrono>

#include "terrain/back_faces_hidden.h"

namespace ig::render {
namespace {
using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}
// The work counters' passes: the method's, then the sky and the
// anti-aliasing post pass (0 where the frame has none).
std::vector<std::string> pass_names_of(const TerrainMethod& method) {
  auto names = method.pass_names();
  names.push_back("sky");
  names.push_back("aa");
  return names;
}
}  // namespace

FrameRenderer::FrameRenderer(const TerrainScene& scene, TerrainMethod& method, const std::string& shader_dir)
    : scene_(scene),
      method_(&method),
      sky_(shader_dir, "sky.vert", "sky.frag"),
      shader_dir_(shader_dir),
      recorder_(pass_names_of(method)),
      empty_vao_(gl::create_vertex_array()) {
  method_->set_pass_recorder(&recorder_);
}

FrameRenderer::~FrameRenderer() { method_->set_pass_recorder(nullptr); }

void FrameRenderer::set_method(TerrainMethod& method) {
  method_->set_pass_recorder(nullptr);
  method_ = &method;
  if (auto names = pass_names_of(method); names != recorder_.pass_names()) recorder_.reset_passes(std::move(names));
  method_->set_pass_recorder(&recorder_);
}

ViewResult FrameRenderer::render(const Camera& world_camera, const gl::RenderTarget& target) {
  // Methods work in terrain-local metres (world origin subtracted in double)
  // and see the scene's Earth curvature through the camera.
  const Camera camera = scene_.local_camera(world_camera);
  ViewResult r;
  recorder_.begin_frame();
  const gl::WorkTally at_start = gl::work_tally();
  method_->set_viewport(target.width(), target.height());
  auto t0 = Clock::now();
  method_->update(camera);
  r.timings.lod_ms = ms_since(t0);

  t0 = Clock::now();
  target.bind();
  // Reversed-Z: clip depth in [0, 1], cleared to 0 (= infinitely far), nearer is greater.
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_GREATER);
  // Terrain faces are counter-clockwise seen from above. An eye under the
  // surface sees their undersides, so they are culled only while it is above.
  if (back_face_culling_ && terrain::back_faces_hidden(scene_.heightfield(), camera.position)) {
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
  } else {
    glDisable(GL_CULL_FACE);
  }
  glClearColor(0.f, 0.f, 0.f, 1.f);
  glClearDepth(0.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (wireframe_) glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  recorder_.begin(recorder_.pass_names().front());  // a multi-pass method opens its own as it goes
  r.method = method_->draw(camera, target);
  recorder_.end();
  if (wireframe_) glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glFinish();
  r.timings.terrain_ms = ms_since(t0);

  t0 = Clock::now();
  const environment::SkyLight& sky = scene_.sky_light();
  sky_.use();
  sky_.set("u_inv_view_proj", glm::inverse(camera.view_projection()));
  sky_.set("u_zenith", sky.sky_zenith);
  sky_.set("u_horizon", sky.sky_horizon);
  sky_.set("u_sun_dir", sky.sun_direction);
  sky_.set("u_glow", sky.horizon_glow);
  sky_.set("u_sun_disc", sky.sun_disc);
  glDisable(GL_CULL_FACE);
  glDepthFunc(GL_GEQUAL);  // only where the depth buffer still holds the clear value
  glDepthMask(GL_FALSE);
  glBindVertexArray(empty_vao_.id());
  recorder_.begin("sky");
  glDrawArrays(GL_TRIANGLES, 0, 3);
  gl::count_draw();
  recorder_.end();
  glDepthMask(GL_TRUE);
  glFinish();
  r.timings.sky_ms = ms_since(t0);
  if (target.samples() > 1 || target.post_pass()) {
    t0 = Clock::now();
    if (target.post_pass()) {
      target.bind_output();
      glDisable(GL_DEPTH_TEST);
      if (!edge_aa_.id()) edge_aa_ = gl::ShaderProgram(shader_dir_, "fullscreen.vert", "edge_aa.frag");
      edge_aa_.use();
      glBindTextureUnit(0, target.drawn_color_texture());
      edge_aa_.set("u_frame", 0);
      recorder_.begin("aa");
      glDrawArrays(GL_TRIANGLES, 0, 3);
      gl::count_draw();
      recorder_.end();
      glEnable(GL_DEPTH_TEST);
    } else {
      target.resolve();
    }
    glFinish();
    r.timings.resolve_ms = ms_since(t0);
  }
  r.passes = recorder_.read();
  r.total.name = "total";
  for (const auto& p : r.passes) {
    r.total.vs_invocations += p.vs_invocations;
    r.total.fs_invocations += p.fs_invocations;
    r.total.primitives += p.primitives;
  }
  // Uploads in update() (outside every pass) count too.
  r.total.draw_calls = gl::work_tally().draw_calls - at_start.draw_calls;
  r.total.bytes_uploaded = gl::work_tally().bytes_uploaded - at_start.bytes_uploaded;
  if (!r.method.passes.empty()) r.method.passes += "+";
  r.method.passes += "sky";
  if (target.post_pass()) r.method.passes += "+aa";
  return r;
}

}  // namespace ig::render
