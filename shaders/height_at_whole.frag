#version 450 core
// height_at for a scene whose whole DEM is one texture and has no window.
uniform sampler2D u_height;  // R32F, linear filtering for normals
uniform ivec2 u_dem_size;

float height_at(vec2 s) { return textureLod(u_height, (s + 0.5) / vec2(u_dem_size), 0.0).r; }
