#version 450 core
// Level0 of the two-level method: where the transition band covers the
// pixel at about the same depth, shade at the blended coordinate
// uv = uv1 * beta + uv0 * (1 - beta) (dynamic branching, as with SM3);
// elsewhere at Level0's own coordinate uv0. uv1 is where the pixel's view
// ray meets the full-resolution surface in the band ring, found one of two ways:
//   target: read from the band pass's RGBA16F target (the paper's pass);
//   inline: by marching the ray against the height texture here, only for
//           fragments whose ray window reaches the grown square (no extra pass);
//           Level0 out of every window's reach is drawn with
//           level0_no_band.frag instead (lod/band_ring.h).
uniform bool u_band_valid;       // the band is drawn this frame
uniform bool u_band_inline;      // inline (true) or target (false)
uniform sampler2D u_band;        // target: rg = uv1 - centre, b = beta, a = mask
uniform sampler2D u_band_depth;  // target: the band pass's depth
uniform vec4 u_band_rect;        // target: pixels (x0, y0, x1, y1) where it is valid
uniform vec2 u_level1_center;    // band coordinates are relative to this (samples)
uniform vec2 u_near_far;
uniform float u_band_tolerance_m;
uniform float u_band_window_per_m;  // the depth window grows by this per metre of distance (lod/band_ring.h)
// inline:
uniform sampler2D u_beta_template;  // 256x256, beta over the grown square
uniform float u_grown_half;         // half side of the grown square (samples)
uniform float u_level1_half;        // half side of Level1's square (samples)
uniform vec2 u_spacing;
uniform ivec2 u_eye_sample;
uniform vec3 u_eye_frac;            // eye - eye_sample * spacing (xy), eye height (z)
uniform float u_earth_radius_m;

float height_at(vec2 s);  // height_at_window.frag or height_at_whole.frag

float view_distance(float depth) {  // reversed-Z depth -> distance along the view axis
  return u_near_far.x * u_near_far.y / (depth * (u_near_far.y - u_near_far.x) + u_near_far.x);
}

vec2 band_uv_from_target(vec2 own) {
  if (any(lessThan(gl_FragCoord.xy, u_band_rect.xy)) || any(greaterThanEqual(gl_FragCoord.xy, u_band_rect.zw))) return own;
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec4 band = texelFetch(u_band, px, 0);
  if (band.a < 0.5) return own;
  float band_d = view_distance(texelFetch(u_band_depth, px, 0).r);
  float own_d = view_distance(gl_FragCoord.z);
  if (abs(band_d - own_d) >= u_band_tolerance_m + u_band_window_per_m * own_d) return own;
  return (u_level1_center + band.rg) * band.b + own * (1.0 - band.b);
}

// Height of the ray point t (metres along dir from the eye) above the
// full-resolution surface as drawn (curvature drop included).
float above_surface(vec2 eye_s, vec3 dir, float t) {
  vec3 p = t * dir;
  float h = height_at(eye_s + p.xy / u_spacing) - u_eye_frac.z;
  if (u_earth_radius_m > 0.0) {
    float r = u_earth_radius_m, d2 = min(dot(p.xy, p.xy), r * r);
    h -= d2 / (r + sqrt(r * r - d2));
  }
  return p.z - h;
}

vec2 band_uv_inline(vec2 own, vec3 rel) {
  float t_own = length(rel);
  vec3 dir = rel / t_own;
  // The band pass's depth window, along the ray.
  float win = u_band_tolerance_m + u_band_window_per_m * t_own;
  float t_lo = max(t_own - win, 0.0), t_hi = t_own + win;
  vec2 eye_s = vec2(u_eye_sample) + u_eye_frac.xy / u_spacing;
  vec2 a = eye_s + t_lo * dir.xy / u_spacing, b = eye_s + t_hi * dir.xy / u_spacing;
  vec2 c = u_level1_center;
  // The window's footprint misses the grown square: no band here (most fragments stop here).
  if (any(greaterThan(min(a, b), c + u_grown_half)) || any(lessThan(max(a, b), c - u_grown_half))) return own;
  // First crossing of the surface from above, near to far, then one secant step.
  const int kSteps = 8;
  float t0 = t_lo, f0 = above_surface(eye_s, dir, t0);
  for (int k = 1; k <= kSteps; ++k) {
    float t1 = mix(t_lo, t_hi, float(k) / float(kSteps));
    float f1 = above_surface(eye_s, dir, t1);
    if (f0 > 0.0 && f1 <= 0.0) {
      float t = t0 + (t1 - t0) * f0 / (f0 - f1);
      vec2 s = eye_s + t * dir.xy / u_spacing;
      vec2 q = abs(s - c);
      if (max(q.x, q.y) > u_grown_half || max(q.x, q.y) < u_level1_half) return own;  // not in the ring
      float beta = texture(u_beta_template, (s - c) / (2.0 * u_grown_half) + 0.5).r;
      return s * beta + own * (1.0 - beta);
    }
    t0 = t1;
    f0 = f1;
  }
  return own;
}

vec2 level0_uv(vec2 own, vec3 rel) {
  if (!u_band_valid) return own;
  return u_band_inline ? band_uv_inline(own, rel) : band_uv_from_target(own);
}
