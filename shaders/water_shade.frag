#version 450 core
// Deferred shading's water pass, second draw (gl/water_pass.h): over the
// frame the shading pass shaded as land, the water's colour (water.frag)
// from the surface targets, fogged like the land (fog.frag), blended by how
// much of the pixel is water. Drawn only on the pixels the shading pass
// marked (water_mark.frag, water_mask.frag), so land costs it nothing. Alpha (the coverage code) is left as the
// terrain pass wrote it.
uniform sampler2D u_surface;
uniform sampler2D u_footprint;
layout(location = 0) out vec4 o_color;

float height_at(vec2 s);                                          // height_at_*.frag
vec3 fogged(vec3 color, float dist);                              // fog.frag
float water_coverage(vec2 s, vec2 s_dx, vec2 s_dy);               // water.frag
vec3 water_colour(vec2 s, vec2 s_dx, vec2 s_dy, float h);         // water.frag

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec4 surface = texelFetch(u_surface, px, 0);
  vec4 footprint = texelFetch(u_footprint, px, 0);
  float cover = water_coverage(surface.xy, footprint.xy, footprint.zw);
  vec3 water = water_colour(surface.xy, footprint.xy, footprint.zw, height_at(surface.xy));
  o_color = vec4(fogged(water, surface.z), cover);
}
