#version 450 core
// Level0 triangles that cross Level1's square: fragments inside the square
// are discarded (Level1 is the surface there); the depth test against
// Level1 keeps a nearer Level0 ridge in front of it.
in vec3 v_rel;
in vec2 v_sample;
uniform float u_alpha;
uniform vec4 u_level1_box;  // Level1 square in samples: min.xy, max.xy
uniform float u_clip_margin;  // samples the square is shrunk by for the test (TerrainScene::bind_common)
layout(location = 0) out vec4 o_color;

vec3 shade(vec2 s, float dist);  // terrain_shading.frag
vec2 level0_uv(vec2 own, vec3 rel);  // level0_blend.frag

void main() {
  if (all(greaterThanEqual(v_sample, u_level1_box.xy + u_clip_margin)) &&
      all(lessThanEqual(v_sample, u_level1_box.zw - u_clip_margin)))
    discard;
  o_color = vec4(shade(level0_uv(v_sample, v_rel), length(v_rel)), u_alpha);
}
