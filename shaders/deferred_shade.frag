#version 450 core
// The terrain's colour from the surface targets a deferred terrain pass wrote
// (shade_deferred.frag), drawn where the depth test finds terrain; alpha (the
// coverage code) is left as the terrain pass wrote it.
uniform sampler2D u_surface;
uniform sampler2D u_footprint;
layout(location = 0) out vec4 o_color;

vec3 shade_at(vec2 s, vec2 s_dx, vec2 s_dy, float dist);  // terrain_shading.frag
// Whether water may be here, for the water pass: water_mark.frag, or
// water_mark_none.frag (nothing) for a scene without water.
void mark_water(vec2 s, vec2 s_dx, vec2 s_dy);

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec4 surface = texelFetch(u_surface, px, 0);
  vec4 footprint = texelFetch(u_footprint, px, 0);
  o_color = vec4(shade_at(surface.xy, footprint.xy, footprint.zw, surface.z), 0.0);
  mark_water(surface.xy, footprint.xy, footprint.zw);
}
