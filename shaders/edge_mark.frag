#version 450 core
// The edge filter's first draw: copies the frame into the picture and marks
// the pixels the filter will change in a depth mask (1 there, 0 elsewhere),
// so that the filter's draw runs on those pixels alone. A branch does not
// spare a CPU rasterizer the work (it runs both sides for a group of pixels),
// an early depth test does.
uniform sampler2D u_frame;
layout(location = 0) out vec4 o_color;

float luma(vec3 c);
vec4 neighbour_lumas(ivec2 px);
bool is_edge(float m, vec4 nsew, out float range);

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec4 centre = texelFetch(u_frame, px, 0);
  o_color = centre;
  float range;
  gl_FragDepth = is_edge(luma(centre.rgb), neighbour_lumas(px), range) ? 1.0 : 0.0;
}
