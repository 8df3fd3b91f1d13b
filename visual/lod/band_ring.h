#pragma once
// Where the band between the two levels can change Level0's shading
// (shaders/level0_blend.frag, the band shaded inline): a Level0 fragment
// takes its coordinate from the full-resolution surface where its ray meets
// it inside the grown square (Level1's square and the band), searching the
// ray within a depth window of tolerance_m + kWindowPerMetre x its distance
// either way. A piece of Level0 farther from the grown square than its
// window reaches can never take it, so it is drawn with a program without
// that search, which a CPU rasterizer would otherwise run for all of its
// fragments. No GL here.

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace ig::lod {

struct BandRing {
  // The window's growth with distance (the shader's u_band_window_per_m).
  static constexpr double kWindowPerMetre = 0.05;
  // The window's constant part for a Level0 mesh: twice its largest
  // vertical error (the shader's u_band_tolerance_m).
  static double tolerance_for(double level0_max_error_m) { return 2.0 * level0_max_error_m; }

  glm::ivec2 lo{0}, hi{-1};  // the grown square, samples (lo > hi: no band)
  glm::dvec3 eye{0.0};       // terrain-local metres
  glm::dvec2 spacing{1.0};   // metres per sample
  double tolerance_m = 0.0;
  double earth_radius_m = 0.0;  // > 0: heights are drawn dropped by the curvature

  // Whether a fragment of a piece of Level0 lying over samples [piece_lo,
  // piece_hi] with heights [z_lo, z_hi] may take the band's coordinate
  // (conservative: true whenever the shader's search could reach the square).
  bool may_reach(glm::ivec2 piece_lo, glm::ivec2 piece_hi, double z_lo, double z_hi) const;
};

}  // namespace ig::lod
