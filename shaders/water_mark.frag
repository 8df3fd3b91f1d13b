#version 450 core
// mark_water for deferred shading's shading pass in a scene with water:
// beside each terrain pixel's colour, whether water may be there (one
// texture read, conservative: water_near in water.frag) in a second output,
// the water pass's mask (gl/water_pass.h). water_mark_none.frag otherwise.
layout(location = 1) out float o_water_mark;

bool water_near(vec2 s, vec2 s_dx, vec2 s_dy);  // water.frag

void mark_water(vec2 s, vec2 s_dx, vec2 s_dy) { o_water_mark = water_near(s, s_dx, s_dy) ? 1.0 : 0.0; }
