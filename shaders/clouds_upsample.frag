#version 450 core
// The half-resolution clouds (shaders/clouds.frag) over the full frame
// (blend ONE, SRC_ALPHA): each pixel takes the bilinear mix of its four
// nearest cloud samples that were marched to about its own depth (within
// 10 % of it, in reversed-Z's 1 / distance; sky matches sky), so the clouds
// in front of a ridge do not bleed onto the sky beside it; where none
// matches, the sample nearest in depth.
layout(location = 0) out vec4 o_color;

uniform sampler2D u_depth;        // the frame's
uniform sampler2D u_cloud_light;  // half resolution: light, share that shows
uniform sampler2D u_cloud_depth;  // half resolution: the depth each was marched to

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  float d = texelFetch(u_depth, px, 0).r;
  ivec2 size = textureSize(u_cloud_light, 0);
  // Sample q of the half-resolution target sits on frame pixel 2q.
  vec2 at = vec2(px) * 0.5;
  ivec2 base = ivec2(floor(at));
  vec2 f = at - vec2(base);
  vec4 sum = vec4(0.0);
  float weights = 0.0, best = 1e30;
  vec4 nearest = vec4(0.0, 0.0, 0.0, 1.0);
  for (int k = 0; k < 4; ++k) {
    ivec2 o = ivec2(k & 1, k >> 1);
    ivec2 q = clamp(base + o, ivec2(0), size - 1);
    float w = (o.x == 1 ? f.x : 1.0 - f.x) * (o.y == 1 ? f.y : 1.0 - f.y);
    float dq = texelFetch(u_cloud_depth, q, 0).r;
    float apart = abs(dq - d) / max(max(dq, d), 1e-30);
    vec4 c = texelFetch(u_cloud_light, q, 0);
    if (apart < 0.1) {
      sum += w * c;
      weights += w;
    }
    if (apart < best) {
      best = apart;
      nearest = c;
    }
  }
  o_color = weights > 1e-4 ? sum / weights : nearest;
}
