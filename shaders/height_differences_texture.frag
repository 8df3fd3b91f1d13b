#version 450 core
// The shading's normal from one filtered read of the DEM's central
// differences (gl/terrain_textures.h): bilinear filtering commutes with
// differences a whole sample apart, so this is what four filtered height
// reads give (height_differences_heights.frag), for a quarter of the reads.
uniform sampler2D u_height_differences;
uniform ivec2 u_dem_size;

vec2 height_differences(vec2 s) { return textureLod(u_height_differences, (s + 0.5) / vec2(u_dem_size), 0.0).rg; }
