#version 450 core
// height_at for a scene with a height window (render/height_window_texture.h)
// or an overview: full resolution from the window where it holds both
// bilinear neighbours, else from the height texture (the whole DEM, or its
// overview).
uniform sampler2D u_height;     // R32F, linear filtering for normals
uniform sampler2D u_height_window;  // full-resolution window, wrap-around (render/height_window_texture.h)
uniform ivec2 u_window_origin;  // the window's south-west sample
uniform ivec2 u_window_size;    // (0, 0): no window
uniform int u_overview_step;    // > 1: u_height is an overview, every u_overview_step-th sample
uniform ivec2 u_dem_size;

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
