#version 450 core
// Regular-grid terrain chunk (reference renderer; later Level1 and grid LODs).
// Vertices are integer sample offsets inside the chunk; the height comes from
// the height texture (vertex texture fetch), so vertices sit exactly on DEM
// samples. Positions are eye-relative (camera-relative rendering).
layout(location = 0) in ivec2 a_local;

uniform sampler2D u_height;   // R32F metres, texelFetch (exact)
uniform ivec2 u_dem_size;     // samples
uniform vec2 u_spacing;       // metres per sample (x east, y north)
uniform ivec2 u_origin;       // chunk origin in samples
uniform vec3 u_origin_rel;    // chunk origin position minus the eye (z: -eye height)
uniform mat4 u_view_proj;     // eye-relative world -> clip

out vec3 v_rel;     // eye-relative world position
out vec2 v_sample;  // DEM sample coordinates
out float v_height; // metres

void main() {
  // Chunks past the DEM's east/north edge collapse onto the edge (zero-area triangles).
  ivec2 local = min(a_local, u_dem_size - 1 - u_origin);
  ivec2 s = u_origin + local;
  float h = texelFetch(u_height, s, 0).r;
  vec3 rel = u_origin_rel + vec3(vec2(local) * u_spacing, h);
  v_rel = rel;
  v_sample = vec2(s);
  v_height = h;
  gl_Position = u_view_proj * vec4(rel, 1.0);
}
