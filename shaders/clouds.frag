#version 450 core
// Cloud layers for the drawn frame (gl/cloud_pass.h), at half its
// resolution: each pixel's view ray (through the top-left pixel of its 2 x 2
// block of the frame) is marched through every layer's slab up to the
// terrain the frame's depth buffer holds there, and the clouds' light and the
// share of the frame behind them that still shows are written with that
// depth; shaders/clouds_upsample.frag blends them over the frame. A layer is cut
// from the ranked noise field (environment/cloud_noise.h) where it exceeds
// 1 - coverage; stratiform decks are that deep everywhere they are cloud,
// cumuliform heaps rise from a flat base higher towards their middles. The
// layers are fixed to the terrain (and drift with the wind), the slabs
// follow the Earth's curvature as the terrain is drawn, and terrain
// pixels under a cloud lose the sun's share of their light (its shadow).
// Layer data: environment/cloud_frame.h.
layout(location = 0) out vec4 o_color;  // the clouds' light, the share of the frame that shows
layout(location = 1) out float o_depth;  // the frame's depth the ray stopped at

uniform sampler2D u_depth;
uniform sampler2D u_noise;
uniform mat4 u_inv_view_proj;   // clip -> eye-relative world (as drawn: curvature included)
uniform vec2 u_viewport;        // the frame's size (this target is half of it)
uniform float u_eye_alt;        // the eye's height above sea level
uniform float u_curve_k;        // 1 / (2 R), 0 for a flat world
uniform float u_pixel_spread;   // metres of footprint per metre of distance, one pixel
uniform int u_layers;
uniform vec4 u_layer[16];
uniform vec3 u_sun;             // towards the sun, unit
uniform vec3 u_sun_light;
uniform vec3 u_sky_top, u_sky_base;
uniform float u_shadow_floor;
uniform float u_fog_k;
uniform vec3 u_fog_color;

const float kFar = 250000.0;
const float kBig = 1e30;

// The share of the light on a cloud's top that diffuses down through optical
// depth tau (two-stream, strongly forward-scattering droplets).
float diffuse_through(float tau) { return 1.0 / (1.0 + 0.05 * tau); }

float fog_of(float d) { return 1.0 - exp(-(u_fog_k * d) * (u_fog_k * d)); }

// The ray's altitude at distance t (dz: its vertical component).
float altitude(float t, float dz, float k2) { return u_eye_alt + t * dz + k2 * t * t; }

// The interval of t where the ray is at or below altitude h: k2 t^2 + dz t + (eye - h) <= 0.
vec2 below(float h, float dz, float k2) {
  float c = u_eye_alt - h;
  if (k2 < 1e-14) {
    if (abs(dz) < 1e-9) return c <= 0.0 ? vec2(-kBig, kBig) : vec2(kBig, -kBig);
    float t0 = -c / dz;
    return dz > 0.0 ? vec2(-kBig, t0) : vec2(t0, kBig);
  }
  float disc = dz * dz - 4.0 * k2 * c;
  if (disc < 0.0) return vec2(kBig, -kBig);
  float q = -0.5 * (dz + (dz >= 0.0 ? 1.0 : -1.0) * sqrt(disc));
  float r1 = q / k2, r2 = abs(q) > 0.0 ? c / q : 0.0;
  return vec2(min(r1, r2), max(r1, r2));
}

// The noise field at eye-relative horizontal position xy for layer i,
// filtered for a footprint of `footprint` metres: beyond the texel size the
// field is averaged and the cut moves towards the layer's mean coverage.
float field(int i, vec2 xy, float footprint, out float blur) {
  vec4 s = u_layer[4 * i + 1];
  vec4 e = u_layer[4 * i + 2];
  vec4 a = u_layer[4 * i + 3];
  vec2 uv = e.xy + mat2(a.xy, a.zw) * xy;
  // Heaps without the two finest octaves: their tops are domes, not spires.
  float lod = max(log2(max(footprint, 1e-3) / s.w), s.y == 1.0 ? 2.0 : 0.0);
  blur = smoothstep(1.0, 5.0, lod);
  return textureLod(u_noise, uv, lod).r;
}

float density(int i, float n, float blur, float alt, out float top_here);

// Layer i's density at distance t along the ray (its altitude and the
// cloud's top above that point with it), the field filtered for `footprint`.
float sample_layer(int i, vec3 dir, float t, float k2, float footprint, out float alt, out float top_here) {
  vec3 p = dir * t;
  alt = altitude(t, dir.z, k2);
  float blur;
  float n = field(i, p.xy, footprint, blur);
  return density(i, n, blur, alt, top_here);
}

// Density (0-1 of the layer's extinction) at altitude alt over noise value
// n; `top_here`: the cloud's top above this point (for its light).
float density(int i, float n, float blur, float alt, out float top_here) {
  vec4 g = u_layer[4 * i];
  vec4 s = u_layer[4 * i + 1];
  float base = g.x, top = g.y, band = max(g.z, 1.0), th = s.x;
  float cover;
  if (th < 0.0) {
    cover = 1.0;
    top_here = top;
  } else if (s.y == 1.0) {
    // A heap: as high as the field is above the cut.
    float q = clamp((n - th) / max(1.0 - th, 1e-3), 0.0, 1.0);
    top_here = base + (top - base) * (1.0 - (1.0 - q) * (1.0 - q));  // steep sides, a rounded top
    cover = smoothstep(0.0, 0.3, q);  // soft edges: a pixel's rays see them thin out
    cover = mix(cover, 1.0 - th, blur);
    top_here = mix(top_here, base + (top - base) * 0.6, blur);
    float soft_top = max(band, 0.2 * (top - base));
    return cover * smoothstep(base - band, base, alt) * (1.0 - smoothstep(top_here - soft_top, top_here, alt));
  } else {
    cover = mix(smoothstep(th - 0.08, th + 0.08, n), 1.0 - th, blur);  // soft edges, wider than a pixel
    top_here = top;
  }
  float texture_var = mix(0.7 + 0.6 * n, 1.0, blur);  // the deck is not uniform
  return cover * texture_var * smoothstep(base - band, base, alt) * (1.0 - smoothstep(top, top + band, alt));
}

void main() {
  ivec2 px = min(ivec2(gl_FragCoord.xy) * 2, ivec2(u_viewport) - 1);
  vec2 ndc = (vec2(px) + 0.5) / u_viewport * 2.0 - 1.0;
  float depth = texelFetch(u_depth, px, 0).r;
  vec4 far_p = u_inv_view_proj * vec4(ndc, 0.5, 1.0);
  vec3 dir = normalize(far_p.xyz / far_p.w);
  float t_end = kFar;
  if (depth > 0.0) {
    vec4 p = u_inv_view_proj * vec4(ndc, depth, 1.0);
    t_end = min(length(p.xyz / p.w), kFar);
  }
  float k2 = u_curve_k * max(1.0 - dir.z * dir.z, 0.0);
  float sun_z = max(u_sun.z, 0.05);
  float cos_sun = dot(dir, u_sun);
  // Where along its first step each ray starts: a hash of the pixel, so the
  // steps leave fine grain rather than terraces or rings.
  uvec2 hp = uvec2(gl_FragCoord.xy);
  uint h = hp.x * 1664525u ^ hp.y * 1013904223u;
  h ^= h >> 16;
  h *= 0x7feb352du;
  h ^= h >> 15;
  float jitter = float(h & 0xffffu) / 65536.0;
  float phase = 0.7 + 0.9 * pow(max(cos_sun, 0.0), 6.0);  // brighter towards the sun (silver lining)

  // Each layer's stretches of the ray, nearest first.
  vec2 seg[8];
  int seg_layer[8];
  int segs = 0;
  for (int i = 0; i < u_layers; ++i) {
    vec4 g = u_layer[4 * i];
    vec2 hi = below(g.y + g.z, dir.z, k2);
    vec2 lo = below(g.x - g.z, dir.z, k2);
    vec2 parts[2];
    int n = 0;
    if (lo.x >= lo.y) {
      parts[n++] = hi;
    } else {
      parts[n++] = vec2(hi.x, min(hi.y, lo.x));
      parts[n++] = vec2(max(hi.x, lo.y), hi.y);
    }
    for (int k = 0; k < n; ++k) {
      vec2 r = vec2(max(parts[k].x, 0.0), min(parts[k].y, t_end));
      if (r.y <= r.x) continue;
      int j = segs++;
      while (j > 0 && seg[j - 1].x > r.x) {
        seg[j] = seg[j - 1];
        seg_layer[j] = seg_layer[j - 1];
        --j;
      }
      seg[j] = r;
      seg_layer[j] = i;
    }
  }

  vec3 light = vec3(0.0);
  float through = 1.0;
  for (int s = 0; s < segs && through > 0.01; ++s) {
    int i = seg_layer[s];
    vec4 g = u_layer[4 * i];
    vec4 sh = u_layer[4 * i + 1];
    // Decks: a fixed number of steps a stretch (their density changes only
    // with coverage), so neighbouring pixels sample alike. Heaps: steps of a
    // quarter of an element, growing with distance (and the field blurred
    // to match) so a long grazing ray still crosses the layer, from a
    // per-pixel start; where the first step enters cloud the entry is found
    // by halving that step four times (so the surface is not terraced by the
    // steps), and from there the steps are a sixteenth of an element.
    float len = seg[s].y - seg[s].x;
    bool heaps = sh.y == 1.0;
    int steps = heaps ? 32 : int(sh.z);
    float element = sh.w * 16.0;
    float t = seg[s].x + (heaps ? jitter * element * 0.25 : 0.0);
    float t_clear = seg[s].x;  // heaps: the last sample in clear air
    bool fine = false;
    for (int k = 0; k < steps && t < seg[s].y; ++k) {
      float dt = !heaps ? len / float(steps)
                 : fine ? max(element * (1.0 / 16.0), t * 0.015)
                        : max(element * 0.25, t * 0.06);
      if (!heaps) t = seg[s].x + (float(k) + 0.5) * dt;
      float t_here = t;
      if (heaps) dt = min(dt, seg[s].y - t_here);  // not past the terrain
      float footprint = max(t_here * u_pixel_spread, heaps ? 0.5 * dt : 0.0);
      float alt, top_here;
      float rho = sample_layer(i, dir, t_here, k2, footprint, alt, top_here);
      if (heaps && rho <= 0.0) {
        t_clear = t_here;
        t += dt;
        continue;
      }
      if (heaps && !fine) {
        float lo = t_clear, hi = t_here;
        for (int b = 0; b < 4; ++b) {
          float mid = 0.5 * (lo + hi), a_mid, top_mid;
          if (sample_layer(i, dir, mid, k2, footprint, a_mid, top_mid) > 0.0) hi = mid;
          else lo = mid;
        }
        t_here = hi;
        rho = sample_layer(i, dir, t_here, k2, footprint, alt, top_here);
        fine = true;
        dt = min(max(element * (1.0 / 16.0), t_here * 0.015), seg[s].y - t_here);
      }
      t = t_here + dt;
      if (rho <= 0.0) continue;
      float ext = g.w * rho;
      // Light: the sun through the cloud above this point (a quarter of the
      // extinction: most light scattered on the way is scattered forwards),
      // the light diffused down from the lit top, and the sky's.
      float above = max(top_here - alt, 0.0) + 30.0;  // even an edge shades itself a little
      float tau_up = g.w * rho * above;
      float sun_t = exp(-0.25 * tau_up / sun_z);
      float diffused = diffuse_through(tau_up);
      float height = clamp((alt - g.x) / max(g.y - g.x, 1.0), 0.0, 1.0);
      vec3 c = u_sun_light * (phase * sun_t + 1.2 * diffused * sun_z) + mix(u_sky_base, u_sky_top, height) * diffused;
      c = 1.0 - exp(-1.3 * c);  // lit tops stay below white, so their relief shows
      c = mix(c, u_fog_color, fog_of(t_here));
      float a = 1.0 - exp(-ext * max(dt, 0.0));
      light += through * a * c;
      through *= 1.0 - a;
      if (through <= 0.01) break;
    }
  }

  // The shadow: the sun's share of a terrain pixel's light goes where a
  // layer between it and the sun is cloud.
  float shade = 1.0;
  if (depth > 0.0 && u_shadow_floor < 1.0 && u_sun.z > 0.0) {
    vec3 p = dir * t_end;
    float alt = altitude(t_end, dir.z, k2);
    float sun_through = 1.0;
    for (int i = 0; i < u_layers; ++i) {
      vec4 g = u_layer[4 * i];
      float mid = 0.5 * (g.x + g.y);
      if (mid <= alt) continue;
      float reach = (mid - alt) / sun_z;
      float blur;
      float n = field(i, p.xy + u_sun.xy * reach, t_end * u_pixel_spread, blur);
      float top_here;
      float rho = density(i, n, blur, mid, top_here);
      float tau = g.w * rho * max(top_here - g.x, 0.0);
      float direct = exp(-0.25 * tau / sun_z);
      sun_through *= direct + (1.0 - direct) * diffuse_through(tau);
    }
    shade = mix(1.0, mix(u_shadow_floor, 1.0, sun_through), 1.0 - fog_of(t_end));
  }
  o_color = vec4(light, through * shade);
  o_depth = depth;
}
