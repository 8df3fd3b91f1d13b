#version 450 core
// Terrain shading shared by every LOD method. The colour of a pixel is a
// function of its DEM texture coordinate (sample space), the coordinate's
// screen derivatives (texture filtering) and its distance only: per-pixel
// normal (central differences) and height at full resolution, a height and
// slope colour ramp (or an imagery texture), one directional light, water
// where the scene has it, fog. So
// methods differ only in where each pixel's coordinate lands, and the colour
// can be computed in the terrain pass (shade_forward.frag) or from those
// values stored per pixel, once per pixel (shade_deferred.frag,
// deferred_shade.frag).
uniform ivec2 u_dem_size;
uniform vec2 u_spacing;
uniform vec2 u_height_range;    // DEM min, max (m)
uniform vec3 u_sun_dir;         // towards the directional light (the sun, or the twilight sky), normalised
uniform vec3 u_light_color;     // its RGB; with u_ambient from the sun's elevation (environment/sky_light.h)
uniform vec3 u_ambient;         // light from the whole sky, RGB

// The DEM's height at s, bilinear: height_at_window.frag (through a
// full-resolution window, over an overview) or height_at_whole.frag (the
// whole DEM in one texture, no window). A CPU rasterizer runs both sides of
// a branch, so what a scene cannot have is not linked.
float height_at(vec2 s);
// Draped imagery at s, filtered for the footprint s_dx, s_dy: imagery.frag,
// or imagery_none.frag for a scene without imagery.
vec3 imagery_at(vec2 s, vec2 s_dx, vec2 s_dy);

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

// Water over the land where the scene has it and shades in the terrain pass:
// water.frag; water_none.frag (the land unchanged) for a scene without
// water, and with deferred shading, whose water has its own pass
// (water_shade.frag).
vec3 water_over(vec3 land, vec2 s, vec2 s_dx, vec2 s_dy, float h);
// The distance fog (fog.frag).
vec3 fogged(vec3 color, float dist);
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
  float h = height_at(s);
  float h01 = clamp((h - u_height_range.x) / span, 0.0, 1.0);
  vec3 albedo = surface_albedo(s, s_dx, s_dy, h01, clamp(slope * 3.0, 0.0, 1.0));
  float diffuse = max(dot(n, u_sun_dir), 0.0);
  vec3 color = water_over(albedo * (u_ambient + u_light_color * diffuse), s, s_dx, s_dy, h);
  return fogged(color, dist);
}
