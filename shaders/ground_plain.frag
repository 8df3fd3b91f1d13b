#version 450 core
// The surface colour of terrain_shading.frag without ground detail: the
// height and slope ramp, or the draped imagery.
uniform bool u_has_imagery;

vec3 imagery_at(vec2 s, vec2 s_dx, vec2 s_dy);  // imagery.frag or imagery_none.frag
vec3 ramp(float h01, float slope);  // terrain_shading.frag

vec3 surface_albedo(vec2 s, vec2 s_dx, vec2 s_dy, float h01, float slope) {
  return u_has_imagery ? imagery_at(s, s_dx, s_dy) : ramp(h01, slope);
}
