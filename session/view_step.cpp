#include "session/view_step.h"

namespace ig::session {

render::ViewResult render_view(render::TerrainScene& scene, render::FrameRenderer& renderer,
                               const render::Camera& camera, const gl::RenderTarget& target) {
  const render::ViewSelection selection = renderer.select(camera, target);
  scene.apply(selection.scene_requests);
  return renderer.draw(selection, target);
}

}  // namespace ig::session
