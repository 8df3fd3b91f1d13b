#version 450 core
// imagery_at for a scene without imagery: never shown (u_has_imagery is
// false), so nothing is read.
vec3 imagery_at(vec2 s, vec2 s_dx, vec2 s_dy) { return vec3(0.0); }
