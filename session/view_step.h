#pragma once
// One view of one frame in the order the session owns: the method's LOD
// selection, then the scene step it asked for (tile prefetches, the height
// window's move and upload), then the passes. The scene is changed here, by
// its owner, and by nothing the renderer or a method does.

#include "gl/render_target.h"
#include "render/camera.h"
#include "render/frame_renderer.h"
#include "render/terrain_scene.h"

namespace ig::session {

render::ViewResult render_view(render::TerrainScene& scene, render::FrameRenderer& renderer,
                               const render::Camera& camera, const gl::RenderTarget& target);

}  // namespace ig::session
