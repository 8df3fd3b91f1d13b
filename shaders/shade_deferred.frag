#version 450 core
// Terrain shaded once per pixel after the terrain passes: a terrain pass
// only stores what the colour is a function of (terrain_shading.frag) in the
// frame's surface targets, and deferred_shade.frag shades each covered pixel
// from them. A CPU rasterizer shades fragments in groups, so a small
// triangle's fragments cost the whole group, a full-screen pass's do not.
layout(location = 1) out vec4 o_surface;    // s, distance (m), 0
layout(location = 2) out vec4 o_footprint;  // ds/dx, ds/dy

vec3 shade(vec2 s, float dist) {
  o_surface = vec4(s, dist, 0.0);
  o_footprint = vec4(dFdx(s), dFdy(s));
  return vec3(0.0);
}
