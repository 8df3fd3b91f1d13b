#pragma once
// One triangle that covers the viewport (the vertex shader, e.g.
// shaders/fullscreen.vert, makes its corners from gl_VertexID, so the vertex
// array is empty), drawn as a named
// pass of the work counters.

#include <string_view>

#include "gl/gl_objects.h"
#include "gl/work_counters.h"

namespace ig::gl {

void draw_fullscreen_triangle(const VertexArray& empty_vao, PassRecorder& recorder, std::string_view pass);

}  // namespace ig::gl
