#version 450 core
// The sky's colour along a direction, without the sun's disc: a gradient by
// the direction's elevation and a glow towards the sun low over the horizon
// (dusk); below the horizon the horizon haze. Shared by the sky pass
// (sky.frag) and what a water surface mirrors (water.frag). Every colour
// comes from the CPU for the sun's elevation (environment/sky_light.h).
uniform vec3 u_sky_zenith;
uniform vec3 u_sky_horizon;
uniform vec3 u_sky_sun;    // towards the sun, unit
uniform vec3 u_sky_glow;   // horizon glow towards the sun (black by day)

vec3 sky_colour(vec3 dir) {
  float el = dir.z;
  vec3 c = mix(u_sky_horizon, u_sky_zenith, sqrt(clamp(el, 0.0, 1.0)));
  // The glow: widest in azimuth and brightest on the horizon, fading within
  // about 10 deg above it; none below it, where the haze must match the
  // terrain's fog.
  if (u_sky_glow != vec3(0.0)) {  // none by day: skip the work
    vec2 h = dir.xy, sun_h = u_sky_sun.xy;
    float toward = dot(h, sun_h) * inversesqrt(max(dot(h, h) * dot(sun_h, sun_h), 1e-12));
    float glow = pow(0.5 + 0.5 * toward, 3.0) * exp(-max(el, 0.0) * 10.0) * smoothstep(-0.004, 0.004, el);
    c += u_sky_glow * glow;
  }
  return c;
}
