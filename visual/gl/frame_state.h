#pragma once
// The fixed-function state one frame is drawn with. Depth is reversed-Z:
// clip depth in [0, 1], cleared to 0 (infinitely far), nearer is greater,
// into a float depth buffer (gl/render_target.h).

namespace ig::gl {

// Into the bound target: clears colour to opaque black and depth to 0, and
// sets the reversed-Z depth test. Terrain faces are counter-clockwise seen
// from above; `cull_back_faces` culls the others (only right while the eye
// is above the terrain).
void begin_frame(bool cull_back_faces);
// The frame's depth test (as begin_frame sets it), for drawing more into a
// frame already begun.
void use_frame_depth_test();
// Polygons drawn as lines (true) or filled.
void set_wireframe(bool on);
// Waits for the GL to finish everything issued: closes a timed stage.
void finish();

// Checks of the frame's depth set-up, for tests: the bound clip depth range
// is [0, 1]; `depth_texture` holds 32-bit floats.
bool clip_depth_zero_to_one();
bool is_float_depth(unsigned depth_texture);
// No GL error raised since the last check.
bool no_gl_error();

}  // namespace ig::gl
