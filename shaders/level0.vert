#version 450 core
// Level0: the static whole-terrain ROAM mesh. Vertices are DEM sample
// indices; heights come from the height texture. Eye-relative positions are
// formed from integer sample differences, so they stay exact far from the
// origin.
layout(location = 0) in ivec2 a_sample;
layout(location = 1) in float a_lift;  // upper-envelope lift (0 without render.twolevel.level0_envelope)

uniform sampler2D u_height;
uniform int u_overview_step;  // > 1: u_height is an overview; Level0 is built on it, so a_sample is a multiple
uniform vec2 u_spacing;
uniform ivec2 u_eye_sample;  // floor(eye / spacing)
uniform vec3 u_eye_frac;     // eye - eye_sample * spacing (xy), eye height (z)
uniform mat4 u_view_proj;
uniform float u_earth_radius_m;  // > 0: Earth curvature on (terrain/earth_curvature.h), 0: flat

out vec3 v_rel;
out vec2 v_sample;

void main() {
  float h = texelFetch(u_height, a_sample / max(u_overview_step, 1), 0).r + a_lift;
  vec3 rel = vec3(vec2(a_sample - u_eye_sample) * u_spacing - u_eye_frac.xy, h - u_eye_frac.z);
  // Curvature: the same drop as terrain_grid.vert.
  if (u_earth_radius_m > 0.0) {
    float r = u_earth_radius_m, d2 = min(dot(rel.xy, rel.xy), r * r);
    rel.z -= d2 / (r + sqrt(r * r - d2));
  }
  v_rel = rel;
  v_sample = vec2(a_sample);
  gl_Position = u_view_proj * vec4(rel, 1.0);
}
