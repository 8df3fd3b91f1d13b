#version 450 core
// Level0 out of the band's reach (lod/band_ring.h): its own coordinate, as
// level0_blend.frag would give every fragment there, without the search.
vec2 level0_uv(vec2 own, vec3 rel) { return own; }
