#version 450 core
// Post-process edge anti-aliasing in the manner of FXAA (Lottes, 2011): a
// pixel on a luma edge is blended with its neighbour across the edge by the
// share of it the edge line would cover, estimated from where the edge ends
// along its direction; a small low-pass term catches single-pixel features.
// One full-screen pass over the single-sampled frame (render/frame_renderer).
uniform sampler2D u_frame;  // linear filtering, clamp to edge
layout(location = 0) out vec4 o_color;

float luma(vec3 c);
float luma_px(ivec2 p);
vec4 neighbour_lumas(ivec2 px);
bool is_edge(float m, vec4 nsew, out float range);
float luma_at(vec2 uv) { return luma(textureLod(u_frame, uv, 0.0).rgb); }

const float kSubpixel = 0.75;       // weight of the low-pass term
// The walk along an edge: steps in pixels, the last ones long (as in
// Lottes's quality presets), 20.5 px in all. Eight shorter steps (21.5 px)
// came out no closer to a supersampled render and made the pass a third
// slower on llvmpipe, where a group of pixels walks as long as its longest.
const int kSteps = 5;
const float kStepSize[kSteps] = float[](1.0, 1.5, 2.0, 4.0, 12.0);

void main() {
  ivec2 size = textureSize(u_frame, 0);
  vec2 texel = 1.0 / vec2(size);
  vec2 uv = gl_FragCoord.xy * texel;
  ivec2 px = ivec2(gl_FragCoord.xy);
  ivec2 lo_px = max(px - 1, ivec2(0)), hi_px = min(px + 1, size - 1);
  vec4 centre = texelFetch(u_frame, px, 0);
  float m = luma(centre.rgb);
  vec4 nsew = neighbour_lumas(px);
  float range;
  if (!is_edge(m, nsew, range)) {  // never taken after edge_mark.frag's mask; kept so the filter stands alone
    o_color = centre;
    return;
  }
  float n = nsew.x, s = nsew.y, e = nsew.z, w = nsew.w;
  float ne = luma_px(hi_px), sw = luma_px(lo_px);
  float nw = luma_px(ivec2(lo_px.x, hi_px.y)), se = luma_px(ivec2(hi_px.x, lo_px.y));

  // Orientation: second differences across rows (a horizontal edge) against
  // those across columns.
  float across_rows = abs(nw + sw - 2.0 * w) + 2.0 * abs(n + s - 2.0 * m) + abs(ne + se - 2.0 * e);
  float across_cols = abs(nw + ne - 2.0 * n) + 2.0 * abs(w + e - 2.0 * m) + abs(sw + se - 2.0 * s);
  bool horizontal = across_rows >= across_cols;

  // The side of the pixel the edge lies on: the neighbour with the steeper step.
  float l1 = horizontal ? s : w, l2 = horizontal ? n : e;
  float g1 = abs(l1 - m), g2 = abs(l2 - m);
  bool first_side = g1 >= g2;
  float gradient = 0.25 * max(g1, g2);
  float step_len = horizontal ? texel.y : texel.x;
  float edge_luma;
  if (first_side) {
    step_len = -step_len;
    edge_luma = 0.5 * (l1 + m);
  } else {
    edge_luma = 0.5 * (l2 + m);
  }
  // Walk along the edge, half a pixel towards the neighbour, both ways,
  // until the luma there leaves the edge's mean.
  vec2 on_edge = uv + (horizontal ? vec2(0.0, 0.5 * step_len) : vec2(0.5 * step_len, 0.0));
  vec2 along = horizontal ? vec2(texel.x, 0.0) : vec2(0.0, texel.y);
  vec2 p1 = on_edge - along, p2 = on_edge + along;
  float d1 = luma_at(p1) - edge_luma, d2 = luma_at(p2) - edge_luma;
  bool done1 = abs(d1) >= gradient, done2 = abs(d2) >= gradient;
  for (int k = 1; k < kSteps && !(done1 && done2); ++k) {
    if (!done1) {
      p1 -= along * kStepSize[k];
      d1 = luma_at(p1) - edge_luma;
      done1 = abs(d1) >= gradient;
    }
    if (!done2) {
      p2 += along * kStepSize[k];
      d2 = luma_at(p2) - edge_luma;
      done2 = abs(d2) >= gradient;
    }
  }
  float dist1 = horizontal ? uv.x - p1.x : uv.y - p1.y;
  float dist2 = horizontal ? p2.x - uv.x : p2.y - uv.y;
  bool nearer1 = dist1 < dist2;
  float nearest = min(dist1, dist2);
  float length_ = dist1 + dist2;
  // The edge line only crosses this pixel when the luma at the nearer end
  // steps the other way from the centre's.
  bool centre_below = m - edge_luma < 0.0;
  bool crosses = ((nearer1 ? d1 : d2) < 0.0) != centre_below;
  float offset = crosses ? 0.5 - nearest / length_ : 0.0;

  // Low-pass term for features a pixel wide.
  float mean = (2.0 * (n + s + e + w) + ne + nw + se + sw) / 12.0;
  float sub = clamp(abs(mean - m) / range, 0.0, 1.0);
  sub = smoothstep(0.0, 1.0, sub);
  float sub_offset = sub * sub * kSubpixel;
  offset = max(offset, sub_offset);

  vec2 final_uv = uv + (horizontal ? vec2(0.0, offset * step_len) : vec2(offset * step_len, 0.0));
  o_color = vec4(textureLod(u_frame, final_uv, 0.0).rgb, centre.a);
}
