#version 450 core
// Chunked LOD (visual/render/chunked_method.*): one shared grid of 33 x 33
// vertex offsets, placed per chunk at u_stride samples per quad, plus a skirt
// ring: a copy of each side's edge vertices that hangs down to u_skirt_bottom
// (absolute metres) and hides cracks between chunks of different levels.
// Skirts on sides lying on the DEM's outer edge stay folded onto the surface
// (u_skirt_sides clears their bit). Eye-relative positions as in
// terrain_grid.vert (integer offsets from u_origin, whose position minus the
// eye comes from the CPU in double); heights by texelFetch.
layout(location = 0) in ivec2 a_local;  // grid offset 0..32
layout(location = 1) in int a_skirt;    // 0: surface; 1..4: skirt on side south, east, north, west

uniform sampler2D u_height;
uniform ivec2 u_dem_size;
uniform vec2 u_spacing;
uniform ivec2 u_origin;       // chunk origin in samples
uniform int u_stride;         // samples per quad
uniform vec3 u_origin_rel;    // u_origin's position minus the eye (z: -eye height)
uniform int u_skirt_sides;    // bit s set: side s has a skirt
uniform float u_skirt_bottom; // metres
uniform mat4 u_view_proj;
uniform float u_earth_radius_m;  // > 0: Earth curvature (terrain/earth_curvature.h)

out vec3 v_rel;
out vec2 v_sample;

void main() {
  // Vertices past the DEM's edges collapse onto the edge (zero-area triangles).
  ivec2 s = clamp(u_origin + a_local * u_stride, ivec2(0), u_dem_size - 1);
  ivec2 local = s - u_origin;
  float h = texelFetch(u_height, s, 0).r;
  if (a_skirt > 0 && (u_skirt_sides & (1 << (a_skirt - 1))) != 0) h = min(h, u_skirt_bottom);
  vec3 rel = u_origin_rel + vec3(vec2(local) * u_spacing, h);
  if (u_earth_radius_m > 0.0) {
    float r = u_earth_radius_m, d2 = min(dot(rel.xy, rel.xy), r * r);
    rel.z -= d2 / (r + sqrt(r * r - d2));
  }
  v_rel = rel;
  v_sample = vec2(s);
  gl_Position = u_view_proj * vec4(rel, 1.0);
}
