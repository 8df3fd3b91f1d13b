#version 450 core
// The shading's normal from four filtered height reads a sample apart
// (height_at: window, overview or whole DEM), for
// terrain with an overview, whose heights are not all in one texture, and
// DEMs too large for a texture of differences
// (TerrainScene::kMaxHeightDifferencesSamples).
float height_at(vec2 s);  // height_at_window.frag or height_at_whole.frag

vec2 height_differences(vec2 s) {
  return vec2(height_at(s + vec2(1, 0)) - height_at(s - vec2(1, 0)),
              height_at(s + vec2(0, 1)) - height_at(s - vec2(0, 1)));
}
