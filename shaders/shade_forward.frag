#version 450 core
// Terrain shaded in the terrain pass itself: each fragment the depth test
// passes is shaded where it is drawn (multisampled frames, and every frame
// when deferred shading is off).
vec3 shade_at(vec2 s, vec2 s_dx, vec2 s_dy, float dist);  // terrain_shading.frag

vec3 shade(vec2 s, float dist) { return shade_at(s, dFdx(s), dFdy(s), dist); }
