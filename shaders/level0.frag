#version 450 core
// Level0 triangles wholly outside Level1's square: no discard, so the depth
// test can reject hidden fragments before they are shaded.
in vec3 v_rel;
in vec2 v_sample;
uniform float u_alpha;
layout(location = 0) out vec4 o_color;

vec3 shade(vec2 s, float dist);  // terrain_shading.frag
vec2 level0_uv(vec2 own, vec3 rel);  // level0_blend.frag

void main() { o_color = vec4(shade(level0_uv(v_sample, v_rel), length(v_rel)), u_alpha); }
