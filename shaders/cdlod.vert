#version 450 core
// CDLOD (visual/render/cdlod_method.*, lod/cdlod_selection.h): one shared
// grid of 33 x 33 vertex offsets drawn per selected node (or node quarter),
// scaled to the node's LOD (2^lod samples per quad), with vertex morphing.
// Over [u_morph_start[l], u_morph_end[l]) of eye distance, a vertex that is
// odd on the LOD l grid slides to its even neighbour (lower sample index),
// height interpolated along the fine mesh's edge; fully morphed, it goes on
// to LOD l+1's factor, and so on (cascade): the final position depends only
// on the sample and the eye, so neighbouring nodes of any LODs share their
// edges exactly (cdlod_vertex() mirrors this on the CPU).
//
// Eye-relative positions from integer sample differences to the eye's sample
// (u_eye_sample, with the rest of the eye position, computed in double on
// the CPU, in u_eye_frac): the same vertex gives bit-identical results in
// every node that draws it, which the morph factors rely on.
layout(location = 0) in ivec2 a_local;  // grid offset 0..32

const int kMaxLods = 16;

uniform sampler2D u_height;
uniform ivec2 u_dem_size;
uniform vec2 u_spacing;
uniform ivec2 u_origin;      // node origin in samples
uniform int u_lod;           // the node's LOD: 2^lod samples per quad
uniform int u_top_lod;       // LODs >= this do not morph
uniform float u_morph_start[kMaxLods];  // metres
uniform float u_morph_end[kMaxLods];
uniform ivec2 u_eye_sample;  // floor(eye / spacing)
uniform vec3 u_eye_frac;     // eye - eye_sample * spacing (xy), eye height (z)
uniform mat4 u_view_proj;
uniform float u_earth_radius_m;  // > 0: Earth curvature (terrain/earth_curvature.h)

out vec3 v_rel;
out vec2 v_sample;

vec3 rel_of(ivec2 p) {
  ivec2 c = clamp(p, ivec2(0), u_dem_size - 1);
  return vec3(vec2(c - u_eye_sample) * u_spacing - u_eye_frac.xy, texelFetch(u_height, c, 0).r - u_eye_frac.z);
}

void main() {
  ivec2 p = u_origin + a_local * (1 << u_lod);
  vec3 rel = rel_of(p);
  vec2 sample_pos = vec2(clamp(p, ivec2(0), u_dem_size - 1));
  for (int l = u_lod; l < u_top_lod; ++l) {
    float m = clamp((length(rel) - u_morph_start[l]) / (u_morph_end[l] - u_morph_start[l]), 0.0, 1.0);
    if (m <= 0.0) break;
    ivec2 target = p - ((p >> l) & 1) * (1 << l);
    if (m >= 1.0) {
      p = target;
      rel = rel_of(p);
      sample_pos = vec2(clamp(p, ivec2(0), u_dem_size - 1));
      continue;
    }
    rel = mix(rel, rel_of(target), m);
    sample_pos = mix(sample_pos, vec2(clamp(target, ivec2(0), u_dem_size - 1)), m);
    break;
  }
  if (u_earth_radius_m > 0.0) {
    float r = u_earth_radius_m, d2 = min(dot(rel.xy, rel.xy), r * r);
    rel.z -= d2 / (r + sqrt(r * r - d2));
  }
  v_rel = rel;
  v_sample = sample_pos;
  gl_Position = u_view_proj * vec4(rel, 1.0);
}
