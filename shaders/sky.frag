#version 450 core
// Sky gradient from the view ray's elevation; below the horizon (beyond the
// DEM's edge) the horizon haze, the same colour the terrain fogs towards.
// Towards the sun a glow low over the horizon (dusk) and the sun's disc.
// Every colour comes from the CPU for the sun's elevation
// (environment/sky_light.h).
in vec2 v_ndc;
uniform mat4 u_inv_view_proj;   // clip -> eye-relative world
uniform vec3 u_zenith;
uniform vec3 u_horizon;
uniform vec3 u_sun_dir;         // towards the sun, unit
uniform vec3 u_glow;            // horizon glow towards the sun (black by day)
uniform vec3 u_sun_disc;        // the disc's colour
layout(location = 0) out vec4 o_color;
void main() {
  vec4 p = u_inv_view_proj * vec4(v_ndc, 0.5, 1.0);
  vec3 dir = normalize(p.xyz / p.w);
  float el = dir.z;
  vec3 c = mix(u_horizon, u_zenith, sqrt(clamp(el, 0.0, 1.0)));
  // The glow: widest in azimuth and brightest on the horizon, fading within
  // about 10 deg above it; none below it, where the haze must match the
  // terrain's fog.
  if (u_glow != vec3(0.0)) {  // none by day: skip the work
    vec2 h = dir.xy, sun_h = u_sun_dir.xy;
    float toward = dot(h, sun_h) * inversesqrt(max(dot(h, h) * dot(sun_h, sun_h), 1e-12));
    float glow = pow(0.5 + 0.5 * toward, 3.0) * exp(-max(el, 0.0) * 10.0) * smoothstep(-0.004, 0.004, el);
    c += u_glow * glow;
  }
  float sun = pow(max(dot(dir, u_sun_dir), 0.0), 400.0);
  c = mix(c, u_sun_disc, sun * step(0.0, el));
  o_color = vec4(min(c, vec3(1.0)), 0.0);  // alpha 0: not terrain (coverage marker)
}
