#version 450 core
// The sky behind the terrain: its colour along the view ray (sky_colour.frag)
// and the sun's disc.
in vec2 v_ndc;
uniform mat4 u_inv_view_proj;   // clip -> eye-relative world
uniform vec3 u_sky_sun;         // towards the sun, unit
uniform vec3 u_sun_disc;        // the disc's colour
layout(location = 0) out vec4 o_color;

vec3 sky_colour(vec3 dir);  // sky_colour.frag

void main() {
  vec4 p = u_inv_view_proj * vec4(v_ndc, 0.5, 1.0);
  vec3 dir = normalize(p.xyz / p.w);
  vec3 c = sky_colour(dir);
  float sun = pow(max(dot(dir, u_sky_sun), 0.0), 400.0);
  c = mix(c, u_sun_disc, sun * step(0.0, dir.z));
  o_color = vec4(min(c, vec3(1.0)), 0.0);  // alpha 0: not terrain (coverage marker)
}
