#version 450 core
// An entity model's vertex: placed by its instance's node matrix (node ->
// eye-relative world metres, computed in double on the CPU, so nothing
// jitters far from the origin) and lowered by the Earth-curvature drop the
// terrain's vertices get (cdlod.vert), so an entity stays on the ground it
// was clamped to however far away it is.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
layout(location = 3) in mat4 a_node_to_eye;  // locations 3-6
layout(location = 7) in float a_alpha;
uniform mat4 u_view_proj;
uniform float u_earth_radius_m;
out vec3 v_rel;
out vec3 v_normal;
out vec2 v_uv;
out float v_alpha;

void main() {
  vec3 rel = (a_node_to_eye * vec4(a_position, 1.0)).xyz;
  if (u_earth_radius_m > 0.0) {
    float r = u_earth_radius_m, d2 = min(dot(rel.xy, rel.xy), r * r);
    rel.z -= d2 / (r + sqrt(r * r - d2));
  }
  v_rel = rel;
  v_normal = mat3(a_node_to_eye) * a_normal;
  v_uv = a_uv;
  v_alpha = a_alpha;
  gl_Position = u_view_proj * vec4(rel, 1.0);
}
