#version 450 core
// Level0 triangles that cross Level1's square: fragments inside the square
// are discarded (Level1 is the surface there); the depth test against
// Level1 keeps a nearer Level0 ridge in front of it.
in vec3 v_rel;
in vec2 v_sample;
uniform float u_alpha;
uniform vec4 u_level1_box;  // Level1 square in samples: min.xy, max.xy
uniform float u_clip_margin;  // samples the square is shrunk by for the test (TerrainScene::bind_common)
// Multisampled frame: a fragment is discarded for all its samples at once, so
// only where the pixel's whole footprint is inside the square; in pixels on
// its edge the depth test picks Level0 or Level1 per sample.
uniform bool u_clip_footprint;
layout(location = 0) out vec4 o_color;

vec3 shade(vec2 s, float dist);  // terrain_shading.frag
vec2 level0_uv(vec2 own, vec3 rel);  // level0_blend.frag

void main() {
  vec2 margin = vec2(u_clip_margin);
  if (u_clip_footprint) margin += 0.5 * (abs(dFdx(v_sample)) + abs(dFdy(v_sample)));
  if (all(greaterThanEqual(v_sample, u_level1_box.xy + margin)) &&
      all(lessThanEqual(v_sample, u_level1_box.zw - margin)))
    discard;
  o_color = vec4(shade(level0_uv(v_sample, v_rel), length(v_rel)), u_alpha);
}
