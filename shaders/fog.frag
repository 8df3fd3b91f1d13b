#version 450 core
// The distance fog every terrain and water colour gets: exponential-squared,
// 98 % at the visibility distance, towards the sky's horizon colour.
uniform vec3 u_fog_color;
uniform float u_fog_k;  // fog factor 1 - exp(-(k d)^2); 0 = no fog

vec3 fogged(vec3 color, float dist) {
  float fog = 1.0 - exp(-(u_fog_k * dist) * (u_fog_k * dist));
  return mix(color, u_fog_color, fog);
}
