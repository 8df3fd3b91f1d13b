#version 450 core
// Counts pixels by the coverage marker in the colour target's alpha (with an
// occlusion query around the draw): Level1 writes 1.0, Level0 0.5, sky 0.
uniform sampler2D u_color;
uniform float u_threshold;
void main() {
  if (texelFetch(u_color, ivec2(gl_FragCoord.xy), 0).a < u_threshold) discard;
}
