#version 450 core
// Sky gradient from the view ray's elevation; below the horizon (beyond the
// DEM's edge) the horizon haze, the same colour the terrain fogs towards.
in vec2 v_ndc;
uniform mat4 u_inv_view_proj;   // clip -> eye-relative world
uniform vec3 u_zenith;
uniform vec3 u_horizon;
uniform vec3 u_sun_dir;
layout(location = 0) out vec4 o_color;
void main() {
  vec4 p = u_inv_view_proj * vec4(v_ndc, 0.5, 1.0);
  vec3 dir = normalize(p.xyz / p.w);
  float el = dir.z;
  vec3 c = mix(u_horizon, u_zenith, sqrt(clamp(el, 0.0, 1.0)));
  float sun = pow(max(dot(dir, u_sun_dir), 0.0), 400.0);
  c = mix(c, vec3(1.0, 0.97, 0.9), sun * step(0.0, el));
  o_color = vec4(c, 0.0);  // alpha 0: not terrain (coverage marker)
}
