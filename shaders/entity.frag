#version 450 core
// An entity's surface, lit like the terrain (terrain_shading.frag): its
// base colour (factor times texture) under the same sun, sky light and
// ambient, then the same distance fog. Alpha: the material's times the
// entity's; a masked material discards below its cutoff.
uniform vec3 u_sun_dir;
uniform vec3 u_light_color;
uniform vec3 u_ambient;
uniform vec4 u_base_color;
uniform int u_has_texture;
uniform sampler2D u_base_texture;
uniform float u_alpha_cutoff;  // < 0: no mask
uniform int u_unlit;
in vec3 v_rel;
in vec3 v_normal;
in vec2 v_uv;
in float v_alpha;
layout(location = 0) out vec4 o_color;

vec3 fogged(vec3 color, float dist);  // fog.frag

void main() {
  vec4 c = u_base_color;
  if (u_has_texture == 1) c *= texture(u_base_texture, v_uv);
  float alpha = c.a * v_alpha;
  if (alpha < u_alpha_cutoff) discard;
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
  vec3 lit = u_unlit == 1 ? c.rgb : c.rgb * (u_ambient + u_light_color * max(dot(n, u_sun_dir), 0.0));
  o_color = vec4(fogged(lit, length(v_rel)), alpha);
}
