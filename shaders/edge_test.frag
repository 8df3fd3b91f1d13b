#version 450 core
// Which pixels the edge anti-aliasing filters: those whose luma differs from
// their four neighbours' by more than the thresholds below (FXAA's early
// exit). Linked into the pass that marks them (edge_mark.frag) and into the
// filter (edge_aa.frag), so both draw the same line.
uniform sampler2D u_frame;

const float kEdgeMin = 1.0 / 16.0;  // ignore edges fainter than this (absolute): the ground's grain stays sharp
const float kEdgeRel = 1.0 / 8.0;   // ... or below this share of the local max

float luma(vec3 c) { return dot(c, vec3(0.299, 0.587, 0.114)); }
float luma_px(ivec2 p) { return luma(texelFetch(u_frame, p, 0).rgb); }  // clamped by the caller

// North, south, east and west of px, clamped to the frame.
vec4 neighbour_lumas(ivec2 px) {
  ivec2 size = textureSize(u_frame, 0);
  ivec2 lo_px = max(px - 1, ivec2(0)), hi_px = min(px + 1, size - 1);
  return vec4(luma_px(ivec2(px.x, hi_px.y)), luma_px(ivec2(px.x, lo_px.y)), luma_px(ivec2(hi_px.x, px.y)),
              luma_px(ivec2(lo_px.x, px.y)));
}

// range: the luma's spread over the pixel and those four neighbours.
bool is_edge(float m, vec4 nsew, out float range) {
  float lo = min(m, min(min(nsew.x, nsew.y), min(nsew.z, nsew.w)));
  float hi = max(m, max(max(nsew.x, nsew.y), max(nsew.z, nsew.w)));
  range = hi - lo;
  return range >= max(kEdgeMin, hi * kEdgeRel);
}
