#version 450 core
// Terrain shading shared by every LOD method. The colour of a pixel is a
// function of its DEM texture coordinate (sample space), the coordinate's
// screen derivatives (texture filtering) and its distance only: per-pixel
// normal (central differences) and height at full resolution, a height and
// slope colour ramp (or an imagery texture), one directional light, fog. So
// methods differ only in where each pixel's coordinate lands, and the colour
// can be computed in the terrain pass (shade_forward.frag) or from those
// values stored per pixel, once per pixel (shade_deferred.frag,
// deferred_shade.frag).
uniform sampler2D u_height;     // R32F, linear filtering for normals
uniform sampler2D u_height_window;  // full-resolution window, wrap-around (render/height_window_texture.h)
uniform ivec2 u_window_origin;  // the window's south-west sample
uniform ivec2 u_window_size;    // (0, 0): no window
uniform int u_overview_step;    // > 1: u_height is an overview, every u_overview_step-th sample
uniform sampler2D u_imagery;    // RGB draped over the DEM (only when u_has_imagery); an overview beyond the limit
uniform bool u_has_imagery;
uniform sampler2D u_imagery_window;     // full-resolution imagery, wrap-around (render/imagery_window_texture.h)
uniform ivec2 u_imagery_window_origin;  // its south-west pixel
uniform ivec2 u_imagery_window_size;    // (0, 0): no imagery window
uniform ivec2 u_imagery_full_size;      // pixels of the full-resolution image over the footprint
uniform float u_imagery_overview_lod;   // log2 of full-resolution pixels per overview pixel
uniform vec2 u_imagery_overview_scale;  // footprint / overview span (whole steps: <= 1; 1 for imagery that fits)
uniform ivec2 u_dem_size;
uniform vec2 u_spacing;
uniform vec2 u_height_range;    // DEM min, max (m)
uniform vec3 u_sun_dir;         // towards the directional light (the sun, or the twilight sky), normalised
uniform vec3 u_light_color;     // its RGB; with u_ambient from the sun's elevation (environment/sky_light.h)
uniform vec3 u_ambient;         // light from the whole sky, RGB
uniform vec3 u_fog_color;
uniform float u_fog_k;          // fog factor 1 - exp(-(k d)^2); 0 = no fog

float height_at(vec2 s) {
  // Inside the window, with the bilinear neighbour too (r <= size - 2: the
  // texel past the window's last wraps to its first), from the window.
  if (u_window_size.x > 0) {
    vec2 r = s - vec2(u_window_origin);
    if (all(greaterThanEqual(r, vec2(0.0))) && all(lessThanEqual(r, vec2(u_window_size - 2))))
      return textureLod(u_height_window, (s + 0.5) / vec2(u_window_size), 0.0).r;
  }
  if (u_overview_step > 1)  // overview sample k is DEM sample k * step
    return textureLod(u_height, (s / float(u_overview_step) + 0.5) / vec2(textureSize(u_height, 0)), 0.0).r;
  return textureLod(u_height, (s + 0.5) / vec2(u_dem_size), 0.0).r;
}

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

vec3 ramp(float h01, float slope) {
  vec3 low = vec3(0.36, 0.45, 0.25);    // valley vegetation
  vec3 mid = vec3(0.47, 0.42, 0.30);    // dry slopes
  vec3 rock = vec3(0.52, 0.50, 0.48);
  vec3 snow = vec3(0.93, 0.94, 0.96);
  vec3 c = mix(low, mid, smoothstep(0.15, 0.45, h01));
  c = mix(c, rock, smoothstep(0.45, 0.75, h01));
  c = mix(c, rock, smoothstep(0.55, 0.85, slope));
  float snow_line = 0.82 + 0.1 * slope;
  return mix(c, snow, smoothstep(snow_line, snow_line + 0.06, h01));
}

// The surface colour before light: ground_plain.frag or ground_detail.frag
// (render/terrain_scene.h, TerrainScene::shading_stages).
vec3 surface_albedo(vec2 s, vec2 s_dx, vec2 s_dy, float h01, float slope);
// (h(s + x) - h(s - x), h(s + y) - h(s - y)) of the bilinear surface:
// height_differences_texture.frag or height_differences_heights.frag.
vec2 height_differences(vec2 s);

vec3 shade_at(vec2 s, vec2 s_dx, vec2 s_dy, float dist) {
  vec2 d = height_differences(s);
  vec3 n = normalize(vec3(-d.x / (2.0 * u_spacing.x), -d.y / (2.0 * u_spacing.y), 1.0));
  float slope = 1.0 - n.z;
  float span = max(u_height_range.y - u_height_range.x, 1.0);
  float h01 = clamp((height_at(s) - u_height_range.x) / span, 0.0, 1.0);
  vec3 albedo = surface_albedo(s, s_dx, s_dy, h01, clamp(slope * 3.0, 0.0, 1.0));
  float diffuse = max(dot(n, u_sun_dir), 0.0);
  vec3 color = albedo * (u_ambient + u_light_color * diffuse);
  float fog = 1.0 - exp(-(u_fog_k * dist) * (u_fog_k * dist));
  return mix(color, u_fog_color, fog);
}
