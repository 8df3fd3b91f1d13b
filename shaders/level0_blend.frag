#version 450 core
// Level0 of the two-level method: where the transition band covers the
// pixel at about the same depth, shade at the blended coordinate
// uv = uv1 * beta + uv0 * (1 - beta) (dynamic branching, as with SM3);
// elsewhere at Level0's own coordinate.
uniform bool u_band_valid;       // the band pass ran this frame
uniform sampler2D u_band;        // RGBA16F: rg = uv1 - centre, b = beta, a = mask
uniform sampler2D u_band_depth;  // the band pass's depth
uniform vec4 u_band_rect;        // pixels (x0, y0, x1, y1): the band target is valid only inside
uniform vec2 u_level1_center;    // band coordinates are relative to this (samples)
uniform vec2 u_near_far;
uniform float u_band_tolerance_m;

float view_distance(float depth) {  // reversed-Z depth -> distance along the view axis
  return u_near_far.x * u_near_far.y / (depth * (u_near_far.y - u_near_far.x) + u_near_far.x);
}

vec2 level0_uv(vec2 own) {
  if (!u_band_valid) return own;
  if (any(lessThan(gl_FragCoord.xy, u_band_rect.xy)) || any(greaterThanEqual(gl_FragCoord.xy, u_band_rect.zw))) return own;
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec4 band = texelFetch(u_band, px, 0);
  if (band.a < 0.5) return own;
  float band_d = view_distance(texelFetch(u_band_depth, px, 0).r);
  float own_d = view_distance(gl_FragCoord.z);
  if (abs(band_d - own_d) >= u_band_tolerance_m + 0.05 * own_d) return own;
  return (u_level1_center + band.rg) * band.b + own * (1.0 - band.b);
}
