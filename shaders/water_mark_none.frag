#version 450 core
// mark_water for a scene without water (water_mark.frag otherwise): nothing.
void mark_water(vec2 s, vec2 s_dx, vec2 s_dy) {}
