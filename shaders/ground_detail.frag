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

vec3 imagery_at(vec2 s);             // terrain_shading.frag
vec3 ramp(float h01, float slope);  // terrain_shading.frag

// The detail texture at tile size k, filtered for this pixel's footprint
// (p is never wrapped, so its derivatives have no seam where a tile repeats).
// Half a mip level sharper than the footprint (bias -0.5): trilinear
// filtering blurs more than the pixel's own box, and so biased the lower
// quarter of a low view has about the texture of a 4x4 supersampled render
// (picture_test). texture(), not textureGrad(): llvmpipe picks the level
// once per 2x2 quad.
vec4 detail(vec2 s, int k) {
  vec2 p = (s - u_detail_anchor) * (u_spacing / u_detail_tile_m[k]) + u_detail_phase[k];
  return texture(u_detail, p, -0.5) - 0.5;
}

// log2 of the detail texels a pixel spans at tile size k: where a feature of
// 2^L texels gets smaller than a pixel (L below this), it is gone.
float detail_lod(vec2 s, int k) {
  vec2 scale = u_spacing / u_detail_tile_m[k] * float(textureSize(u_detail, 0).x);
  vec2 dx = dFdx(s) * scale, dy = dFdy(s) * scale;
  return 0.5 * log2(max(max(dot(dx, dx), dot(dy, dy)), 1e-12));
}

// Materials from height, slope and noise: the noise moves every boundary, so
// vegetation, soil, rock and snow meet along soft irregular edges, and each
// has its own grain. Zero-mean detail: far away (the texture's top mips) the
// colour fades to the material's mean instead of sparkling.
vec3 ground_albedo(vec2 s, float h01, float slope, out float grain) {
  vec4 fine = detail(s, 0), mid = detail(s, 1), broad = detail(s, 2);
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
  shrubs = mix(shrubs, 0.25, smoothstep(2.5, 4.5, detail_lod(s, 1)));
  c *= 1.0 - 0.35 * veg * shrubs;
  float rock = smoothstep(0.50, 0.80, sl) * (1.0 - smoothstep(0.85, 0.92, h));
  c *= 1.0 + rock * (0.5 * mid.b + 0.35 * fine.g);
  grain = 0.55 * fine.r + 0.35 * mid.r + 0.25 * fine.g;
  return c * (1.0 + grain);
}

// Over draped imagery, the image's own colours with the grain finer than its pixels.
vec3 surface_albedo(vec2 s, float h01, float slope) {
  float grain;
  vec3 ground = ground_albedo(s, h01, slope, grain);
  return u_has_imagery ? imagery_at(s) * (1.0 + grain) : ground;
}
