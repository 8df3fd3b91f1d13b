#version 450 core
// water_over where the terrain pass shades (forward shading, e.g.
// multisampled frames): the land with the water over it (water.frag).
// Deferred shading links water_none.frag instead and draws the water in a
// pass of its own.
float water_coverage(vec2 s, vec2 s_dx, vec2 s_dy);        // water.frag
vec3 water_colour(vec2 s, vec2 s_dx, vec2 s_dy, float h);  // water.frag

vec3 water_over(vec3 land, vec2 s, vec2 s_dx, vec2 s_dy, float h) {
  float cover = water_coverage(s, s_dx, s_dy);
  if (cover <= 0.0) return land;  // a GPU skips the rest where a whole group is land
  return mix(land, water_colour(s, s_dx, s_dy, h), cover);
}
