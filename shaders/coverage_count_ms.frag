#version 450 core
// coverage_count.frag for a multisampled frame: the marker of each pixel's
// first sample (a resolved edge pixel would hold a mix of two markers).
uniform sampler2DMS u_color;
uniform float u_threshold;
uniform int u_step;
void main() {
  ivec2 p = min(ivec2(gl_FragCoord.xy) * u_step + u_step / 2, textureSize(u_color) - 1);
  if (texelFetch(u_color, p, 0).a < u_threshold) discard;
}
