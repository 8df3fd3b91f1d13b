#version 450 core
// Draped imagery (TerrainScene with an imagery file): one texture, or its
// overview with full resolution in a window around the view.
uniform sampler2D u_imagery;    // RGB draped over the DEM; an overview beyond the limit
uniform sampler2D u_imagery_window;     // full-resolution imagery, wrap-around (render/imagery_window_texture.h)
uniform ivec2 u_imagery_window_origin;  // its south-west pixel
uniform ivec2 u_imagery_window_size;    // (0, 0): no imagery window
uniform ivec2 u_imagery_full_size;      // pixels of the full-resolution image over the footprint
uniform float u_imagery_overview_lod;   // log2 of full-resolution pixels per overview pixel
uniform vec2 u_imagery_overview_scale;  // footprint / overview span (whole steps: <= 1; 1 for imagery that fits)
uniform ivec2 u_dem_size;

// s_dx, s_dy: the screen derivatives of s.
vec3 imagery_at(vec2 s, vec2 s_dx, vec2 s_dy) {
  vec2 uv = (s + 0.5) / vec2(u_dem_size);
  if (u_imagery_window_size.x > 0) {
    // Full-resolution pixel coordinates (pixel k centred at k + 0.5) and
    // their screen derivatives.
    vec2 to_full = vec2(u_imagery_full_size) / vec2(u_dem_size);
    vec2 p = uv * vec2(u_imagery_full_size);
    vec2 px = s_dx * to_full, py = s_dy * to_full;
    vec2 r = p - 0.5 - vec2(u_imagery_window_origin);
    // The window where both bilinear neighbours are in it. The window has no
    // mipmaps, so as a whole texture's trilinear filter would: level 0 alone
    // where the image is magnified (lod <= 0), blended towards the overview
    // (a box mean, i.e. the level u_imagery_overview_lod of a mip chain)
    // up to that level; beyond it, or outside the window, the overview with
    // its own mipmaps.
    bool inside = all(greaterThanEqual(r, vec2(0.0))) && all(lessThanEqual(r, vec2(u_imagery_window_size - 1)));
    float lod = 0.5 * log2(max(max(dot(px, px), dot(py, py)), 1e-12));
    if (inside && lod < u_imagery_overview_lod) {
      vec3 w = textureLod(u_imagery_window, p / vec2(u_imagery_window_size), 0.0).rgb;
      if (lod <= 0.0) return w;
      return mix(w, textureLod(u_imagery, uv * u_imagery_overview_scale, 0.0).rgb, lod / u_imagery_overview_lod);
    }
    vec2 to_overview = u_imagery_overview_scale / vec2(u_imagery_full_size);
    return textureGrad(u_imagery, uv * u_imagery_overview_scale, px * to_overview, py * to_overview).rgb;
  }
  vec2 to_uv = u_imagery_overview_scale / vec2(u_dem_size);  // scale 1 for imagery that fits
  return textureGrad(u_imagery, uv * u_imagery_overview_scale, s_dx * to_uv, s_dy * to_uv).rgb;
}
