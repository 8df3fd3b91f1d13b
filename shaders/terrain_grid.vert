#version 450 core
// Regular-grid terrain (reference chunks, Level1 blocks and walls, the
// transition band). Vertices are integer sample offsets from u_origin,
// clamped onto the DEM; the height comes from the height texture (vertex
// texture fetch), so vertices sit exactly on DEM samples. Positions are
// eye-relative (camera-relative rendering).
layout(location = 0) in ivec2 a_local;
layout(location = 1) in vec2 a_wall;   // wall vertices: (1, z) = at absolute height z ((0, 0) when unbound)

uniform sampler2D u_height;   // R32F metres, texelFetch (exact)
uniform sampler2D u_height_window;  // the same heights around a point, wrap-around (render/height_window_texture.h)
uniform ivec2 u_window_origin;
uniform ivec2 u_window_size;  // (0, 0): no window
uniform int u_overview_step;  // > 1: u_height is an overview (outside the window: its nearest sample below)
uniform ivec2 u_dem_size;     // samples
uniform vec2 u_spacing;       // metres per sample (x east, y north)
uniform ivec2 u_origin;       // grid origin in samples (may lie outside the DEM)
uniform vec3 u_origin_rel;    // u_origin's position minus the eye (z: -eye height)
uniform mat4 u_view_proj;     // eye-relative world -> clip
uniform float u_earth_radius_m;  // > 0: Earth curvature on (terrain/earth_curvature.h), 0: flat

out vec3 v_rel;     // eye-relative world position
out vec2 v_sample;  // DEM sample coordinates

void main() {
  // Vertices past the DEM's edges collapse onto the edge (zero-area triangles).
  ivec2 s = clamp(u_origin + a_local, ivec2(0), u_dem_size - 1);
  ivec2 local = s - u_origin;
  ivec2 w = s - u_window_origin;
  bool in_window = u_window_size.x > 0 && all(greaterThanEqual(w, ivec2(0))) && all(lessThan(w, u_window_size));
  float h = a_wall.x > 0.5 ? a_wall.y
          : in_window      ? texelFetch(u_height_window, s % max(u_window_size, ivec2(1)), 0).r
                           : texelFetch(u_height, s / max(u_overview_step, 1), 0).r;
  vec3 rel = u_origin_rel + vec3(vec2(local) * u_spacing, h);
  // Curvature: drop below the eye's tangent plane, d^2 / (R + sqrt(R^2 - d^2))
  // (no cancellation in float; the same formula as terrain::curvature_drop).
  if (u_earth_radius_m > 0.0) {
    float r = u_earth_radius_m, d2 = min(dot(rel.xy, rel.xy), r * r);
    rel.z -= d2 / (r + sqrt(r * r - d2));
  }
  v_rel = rel;
  v_sample = vec2(s);
  gl_Position = u_view_proj * vec4(rel, 1.0);
}
