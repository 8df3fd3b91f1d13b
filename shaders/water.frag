#version 450 core
// Water over the terrain where the scene has it (water/water_map.h; linked
// only then): how much of a pixel is water and its colour, used in the
// terrain pass (water_in_shading.frag) or, with deferred shading, in a pass
// of its own over the shaded frame (water_mark.frag, water_shade.frag).
// The data made the surface under the water level (the flattened bed is the
// water's surface), so the water is drawn on the terrain's own surface, the
// same for every LOD method, and the shore is where the share of water
// around each sample (water/shore_field.h) is one half: smooth along any
// coast, anti-aliased over the pixel's footprint, the share itself far
// away. The surface: waves
// as slopes fixed to the terrain (water/wave_slopes.h; two tile sizes
// drifting with time, filtered with distance, their hidden slopes widening
// the glint), the sky mirrored by Fresnel (Schlick, water's 0.02), the sun's
// glint from Cox and Munk's slope distribution, and under it the water's own
// dark colour in the light of the sky and the sun.
uniform sampler2D u_water_share;   // R8, mipmapped: the share of water (water/shore_field.h)
uniform vec2 u_water_share_size;   // its texels
uniform float u_water_step;        // DEM samples a texel (> 1 over an overview)
uniform sampler2D u_waves;         // RGBA16F, tiling: slope x, slope y, their squares
uniform sampler2D u_water_presence;  // R8 levels: where water shows (water/water_presence.h)
uniform float u_water_presence_block;  // share texels a presence texel spans at level 0
uniform float u_wave_tile_m[2];
uniform vec2 u_wave_phase[2];      // each layer's tile position at the anchor and time (CPU, double)
uniform float u_wave_unresolved;   // slope variance per axis the texture does not hold
uniform float u_wave_variance;     // the whole sea's slope variance per axis (Cox-Munk)
uniform vec2 u_water_anchor;       // a whole sample near the eye
uniform vec3 u_water_eye;          // the eye: x, y from the anchor's position, z its height (m)
uniform float u_earth_radius_m;    // the curvature drop's radius; 0 = flat
uniform vec3 u_sun_light;          // the sun's own light at the surface (0 once it has set)
uniform vec3 u_sky_sun;            // towards the sun
uniform vec2 u_spacing;
uniform vec3 u_sun_dir;            // the directional light (terrain_shading.frag)
uniform vec3 u_light_color;
uniform vec3 u_ambient;

vec3 sky_colour(vec3 dir);  // sky_colour.frag

const float kGlint = 9.0;
const vec3 kWaterBody = vec3(0.035, 0.080, 0.090);  // what scatters up from below, per unit light

// How much of the pixel is water: the share's half line anti-aliased over
// the footprint while it spans under two texels, the share (its mips: the
// water's part of the footprint) beyond.
float water_coverage(vec2 s, vec2 s_dx, vec2 s_dy) {
  vec2 to_tc = 1.0 / (u_water_step * u_water_share_size);
  vec2 tc = (s / u_water_step + 0.5) / u_water_share_size;
  float far_share = textureGrad(u_water_share, tc, s_dx * to_tc, s_dy * to_tc).r;
  float texels = max(length(s_dx), length(s_dy)) / u_water_step;
  float share = textureLod(u_water_share, tc, 0.0).r;
  float across = abs(textureLod(u_water_share, tc + s_dx * to_tc, 0.0).r - share) +
                 abs(textureLod(u_water_share, tc + s_dy * to_tc, 0.0).r - share);
  float edge = clamp((share - 0.5) / max(across, 1e-4) + 0.5, 0.0, 1.0);
  return mix(edge, far_share, smoothstep(1.0, 2.0, texels));
}

// Whether any water can be in the pixel: one bilinear read of the presence
// level whose blocks span its footprint (water/water_presence.h: the 2 x 2
// texels around the pixel's centre hold all of its footprint). The water
// pass's mask.
bool water_near(vec2 s, vec2 s_dx, vec2 s_dy) {
  float texels = max(length(s_dx), length(s_dy)) / u_water_step;
  float level = ceil(log2(max(texels / u_water_presence_block, 1.0)));
  vec2 tc = (s / u_water_step + 0.5) / (u_water_presence_block * vec2(textureSize(u_water_presence, 0)));
  return textureLod(u_water_presence, tc, level).r > 0.0;
}

// Wave layer k's mean slope and squared slope over the pixel's footprint.
vec4 waves(vec2 s, vec2 s_dx, vec2 s_dy, int k) {
  vec2 to_tile = u_spacing / u_wave_tile_m[k];
  vec2 p = (s - u_water_anchor) * to_tile + u_wave_phase[k];
  return textureGrad(u_waves, p, s_dx * to_tile, s_dy * to_tile);
}

float fresnel(float cos_theta) { return 0.02 + 0.98 * pow(1.0 - clamp(cos_theta, 0.0, 1.0), 5.0); }

// The water's colour at s (before fog), h the surface's height there.
vec3 water_colour(vec2 s, vec2 s_dx, vec2 s_dy, float h) {
  // From the eye to the surface, lowered by the Earth's curvature as drawn.
  vec2 across = (s - u_water_anchor) * u_spacing - u_water_eye.xy;
  float drop = u_earth_radius_m > 0.0 ? dot(across, across) / (2.0 * u_earth_radius_m) : 0.0;
  vec3 v = normalize(vec3(across, h - drop - u_water_eye.z));
  vec4 w0 = waves(s, s_dx, s_dy, 0), w1 = waves(s, s_dx, s_dy, 1);
  vec2 slope = w0.xy + w1.xy;
  vec2 variance = max(w0.zw - w0.xy * w0.xy, 0.0) + max(w1.zw - w1.xy * w1.xy, 0.0) + u_wave_unresolved;
  vec3 n = normalize(vec3(-slope, 1.0));
  // The sky the waves mirror (never below the horizon: a wave that would
  // mirror the sea mirrors its far edge), and the water's own colour.
  vec3 r = reflect(v, n);
  r.z = max(r.z, 0.0);
  float f = fresnel(dot(-v, n));
  vec3 body = kWaterBody * (u_ambient + u_light_color * max(u_sun_dir.z, 0.0));
  vec3 c = mix(body, sky_colour(normalize(r)), f);
  // The glint: the facets whose normal is the half vector between the eye
  // and the sun, at Cox and Munk's Gaussian density of their slopes about
  // the pixel's mean slope, relative to the density of the whole sea's
  // slopes (so a far pixel, its ripples filtered into its variance, glints
  // as the sea does on average, a near one sparkles); times Fresnel at the
  // sun. A display's scale, not the sun's radiance: kGlint puts the mirror
  // point of a 25-degree sun at the top of the range.
  vec3 half_v = normalize(u_sky_sun - v);
  if (half_v.z > 0.0 && u_sky_sun.z > 0.0) {
    vec2 z = -half_v.xy / half_v.z - slope;
    float density = exp(-0.5 * (z.x * z.x / variance.x + z.y * z.y / variance.y)) * u_wave_variance /
                    sqrt(variance.x * variance.y);
    c += u_sun_light * min(kGlint * fresnel(dot(half_v, u_sky_sun)) * density, 4.0);
  }
  return c;
}

