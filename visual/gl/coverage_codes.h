#pragma once
// What each pass writes into the colour target's alpha: a coverage code that
// the two-level method's count pass reads back (shaders/coverage_count*.frag)
// to measure how much of the terrain Level1 covers. Thresholds lie halfway
// between codes, so filtering and resolves that blend neighbouring codes
// still count on the right side.

namespace ig::gl::coverage {

constexpr float kSky = 0.0f;      // no terrain (the sky pass)
constexpr float kLevel0 = 0.5f;   // terrain from a coarse level (two-level's Level0)
constexpr float kLevel1 = 1.0f;   // full-resolution terrain (Level1, and every single-level method)

constexpr float kAtLeastLevel1 = 0.5f * (kLevel0 + kLevel1);  // 0.75: counted as Level1
constexpr float kAnyTerrain = 0.5f * (kSky + kLevel0);        // 0.25: counted as terrain

}  // namespace ig::gl::coverage
