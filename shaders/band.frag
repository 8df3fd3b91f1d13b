#version 450 core
// Pass 2 of the two-level method: the transition band (Level1's grid grown
// by w_trans) writes its own texture coordinate, relative to the Level1
// centre so half floats keep sub-sample precision, the blend weight beta
// from the template, and a mask.
in vec3 v_rel;
in vec2 v_sample;
uniform sampler2D u_beta_template;  // 256x256, beta over the grown square
uniform vec2 u_level1_center;       // samples
uniform float u_grown_half;         // half side of the grown square (samples)
layout(location = 0) out vec4 o_band;
void main() {
  vec2 rel = v_sample - u_level1_center;
  vec2 t = rel / (2.0 * u_grown_half) + 0.5;
  float beta = texture(u_beta_template, t).r;
  o_band = vec4(rel, beta, 1.0);
}
