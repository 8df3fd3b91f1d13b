#version 450 core
// water_over for a terrain pass that does not shade water (water_in_shading.frag
// otherwise): the land as it is. A scene without water links no water
// shading at all and pays nothing for it; with deferred shading the water
// has a pass of its own.
vec3 water_over(vec3 land, vec2 s, vec2 s_dx, vec2 s_dy, float h) { return land; }
