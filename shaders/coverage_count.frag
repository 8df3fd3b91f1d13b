#version 450 core
// Counts pixels by the coverage marker in the colour target's alpha (with an
// occlusion query around the draw): Level1 writes 1.0, Level0 0.5, sky 0.
// Drawn into a viewport u_step times smaller each way, sampling every
// u_step-th pixel: R is a ratio of two counts on the same samples.
uniform sampler2D u_color;
uniform float u_threshold;
uniform int u_step;
void main() {
  ivec2 p = min(ivec2(gl_FragCoord.xy) * u_step + u_step / 2, textureSize(u_color, 0) - 1);
  if (texelFetch(u_color, p, 0).a < u_threshold) discard;
}
