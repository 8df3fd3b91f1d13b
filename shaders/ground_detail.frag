#version 450 core
// The surface colour of terrain_shading.frag with ground detail
// (render.ground_detail; render/terrain_scene.cpp, terrain/detail_noise.h): a
// tileable noise texture (r fine grain, g clumps, b patches, a broad swells),
// mipmapped, fixed to the terrain at three tile sizes. A tile's coordinate is
// (s - anchor) * spacing / tile + phase, the anchor a whole sample near the
// eye and the phase its position in the tile computed in double on the CPU,
// so it is as exact as s itself however far the terrain reaches.
uniform sampler2D u_detail;
uniform vec2 u_detail_anchor;
uniform float u_detail_tile_m[3];
uniform vec2 u_detail_phase[3];
uniform vec2 u_spacing;
uniform bool u_has_imagery;

vec3 imagery_at(vec2 s, vec2 s_dx, vec2 s_dy);  // imagery.frag or imagery_none.frag
vec3 ramp(float h01, float slope);  // terrain_shading.frag

// The detail texture at tile size k, filtered for this pixel's footprint
// (s_dx, s_dy: the screen derivatives of s; p is never wrapped, so they have
// no seam where a tile repeats). Half a mip level sharper than the footprint
// (derivatives scaled by 2^-0.5): trilinear filtering blurs more than the
// pixel's own box, and so sharpened the lower quarter of a low view has about
// the texture of a 4x4 supersampled render (picture_test).
vec4 detail(vec2 s, vec2 s_dx, vec2 s_dy, int k) {
  vec2 to_tile = u_spacing / u_detail_tile_m[k];
  vec2 p = (s - u_detail_anchor) * to_tile + u_detail_phase[k];
  const float kSharpen = 0.70710678;
  return textureGrad(u_detail, p, s_dx * to_tile * kSharpen, s_dy * to_tile * kSharpen) - 0.5;
}

// log2 of the detail texels a pixel spans at tile size k: where a feature of
// 2^L texels gets smaller than a pixel (L below this), it is gone.
float detail_lod(vec2 s_dx, vec2 s_dy, int k) {
  vec2 scale = u_spacing / u_detail_tile_m[k] * float(textureSize(u_detail, 0).x);
  vec2 dx = s_dx * scale, dy = s_dy * scale;
  return 0.5 * log2(max(max(dot(dx, dx), dot(dy, dy)), 1e-12));
}

// Materials from height, slope and noise: the noise moves every boundary, so
// vegetation, soil, rock and snow meet along soft irregular edges, and each
// has its own grain. Zero-mean detail: far away (the texture's top mips) the
// colour fades to the material's mean instead of sparkling.
vec3 ground_albedo(vec2 s, vec2 s_dx, vec2 s_dy, float h01, float slope, out float grain) {
  vec4 fine = detail(s, s_dx, s_dy, 0), mid = detail(s, s_dx, s_dy, 1), broad = detail(s, s_dx, s_dy, 2);
  float h = h01 + 0.10 * broad.a + 0.05 * broad.b + 0.02 * mid.g;
  float sl = slope + 0.45 * broad.b + 0.25 * mid.g;
  vec3 c = ramp(clamp(h, 0.0, 1.0), clamp(sl, 0.0, 1.0));
  // Vegetation thins into bare soil in patches (sagebrush and grass over
  // sand), rock shows strata-like streaks, snow stays smooth.
  float veg = (1.0 - smoothstep(0.30, 0.55, h)) * (1.0 - smoothstep(0.45, 0.80, sl));
  float bare = smoothstep(-0.05, 0.12, broad.b + 0.6 * mid.b);
  vec3 soil = vec3(0.55, 0.49, 0.38);
  c = mix(c, soil, 0.55 * veg * bare);
  // Shrubs: sharp-edged clumps (8 texels at the middle tile, ~3 m) while
  // they span pixels; farther, their share of the ground (about a quarter),
  // since a threshold of the filtered noise would thin them out with distance.
  float shrubs = smoothstep(0.02, 0.22, mid.g + 0.5 * fine.g);
  shrubs = mix(shrubs, 0.25, smoothstep(2.5, 4.5, detail_lod(s_dx, s_dy, 1)));
  c *= 1.0 - 0.35 * veg * shrubs;
  float rock = smoothstep(0.50, 0.80, sl) * (1.0 - smoothstep(0.85, 0.92, h));
  c *= 1.0 + rock * (0.5 * mid.b + 0.35 * fine.g);
  grain = 0.55 * fine.r + 0.35 * mid.r + 0.25 * fine.g;
  return c * (1.0 + grain);
}

// Over draped imagery, the image's own colours with the grain finer than its pixels.
vec3 surface_albedo(vec2 s, vec2 s_dx, vec2 s_dy, float h01, float slope) {
  float grain;
  vec3 ground = ground_albedo(s, s_dx, s_dy, h01, slope, grain);
  return u_has_imagery ? imagery_at(s, s_dx, s_dy) * (1.0 + grain) : ground;
}
