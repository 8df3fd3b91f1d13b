#version 450 core
// Deferred shading's water pass, first draw (gl/water_pass.h): the marks the
// shading pass wrote (water_mark.frag) into a depth mask, 1 where water may
// be, 0 elsewhere, so that the second draw (water_shade.frag) runs on those
// pixels alone. A branch does not spare a CPU rasterizer the work (it runs
// both sides for a group of pixels), an early depth test does.
uniform sampler2D u_water_mark;

void main() { gl_FragDepth = texelFetch(u_water_mark, ivec2(gl_FragCoord.xy), 0).r > 0.0 ? 1.0 : 0.0; }
