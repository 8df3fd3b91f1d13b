#version 450 core
// Plain terrain pixels (reference chunks, Level1, grid LODs): shaded at their
// own DEM coordinate; alpha is a coverage marker (u_alpha).
in vec3 v_rel;
in vec2 v_sample;
uniform float u_alpha;
layout(location = 0) out vec4 o_color;

vec3 shade(vec2 s, float dist);  // terrain_shading.frag

void main() { o_color = vec4(shade(v_sample, length(v_rel)), u_alpha); }
