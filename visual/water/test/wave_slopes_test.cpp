// The waves' slope texture and where it is: tileable, zero-mean, with the
// slope variance it promises; a tile coordinate that does not depend on the
// anchor however far from the origin; drifting with time.
#include "water/wave_slopes.h"

#include <gtest/gtest.h>

#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace ig::water {
namespace {

TEST(WaveSlopes, ZeroMeanWithTheLayersVarianceAndFinite) {
  const WaveSlopes w = make_wave_slopes(128);
  ASSERT_EQ(w.rgba.size(), 128u * 128u * 4u);
  double sx = 0, sy = 0, vx = 0, vy = 0;
  for (std::size_t k = 0; k < w.rgba.size(); k += 4) {
    for (int c = 0; c < 4; ++c) ASSERT_TRUE(std::isfinite(w.rgba[k + c]));
    sx += w.rgba[k];
    sy += w.rgba[k + 1];
    vx += w.rgba[k + 2];
    vy += w.rgba[k + 3];
    EXPECT_NEAR(w.rgba[k + 2], w.rgba[k] * w.rgba[k], 1e-6);
  }
  const double n = 128.0 * 128.0;
  EXPECT_NEAR(sx / n, 0.0, 1e-4);
  EXPECT_NEAR(sy / n, 0.0, 1e-4);
  // x and y together hold twice the per-axis variance.
  EXPECT_NEAR((vx + vy) / n, 2.0 * kLayerSlopeVariance, 1e-4);
  EXPECT_GT(kUnresolvedSlopeVariance, 0.0);
  EXPECT_NEAR(kSeaSlopeVariance, (0.003 + 5.12e-3 * kWindMs) / 2.0, 1e-12);  // Cox and Munk
}

TEST(WaveSlopes, TilesWithoutASeam) {
  // Across the tile's edge the slopes change no more than between neighbours inside it.
  const WaveSlopes w = make_wave_slopes(64);
  auto at = [&](int x, int y) { return w.rgba[(std::size_t(y) * 64 + x) * 4]; };
  double inside = 0.0, seam = 0.0;
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x + 1 < 64; ++x) inside = std::max(inside, double(std::abs(at(x + 1, y) - at(x, y))));
    seam = std::max(seam, double(std::abs(at(0, y) - at(63, y))));
  }
  EXPECT_LE(seam, inside);
  EXPECT_THROW(make_wave_slopes(100), std::invalid_argument);
}

TEST(WaveSlopes, PhaseDoesNotDependOnTheAnchorFarFromTheOrigin) {
  // A point's tile coordinate, phase(anchor) + (s - anchor) * spacing / tile,
  // is the same (up to whole tiles) from anchors 1e5 samples apart, at a
  // time of a day's simulation.
  const glm::dvec2 spacing(92.6, 74.1);
  const glm::dvec2 s(123456.25, 98765.75);
  for (int k = 0; k < kWaveLayers; ++k) {
    const double tile = wave_layer(k).tile_m;
    auto coord = [&](glm::dvec2 anchor) {
      const glm::dvec2 c = wave_phase(anchor, spacing, k, 86400.0) + (s - anchor) * spacing / tile;
      return c - glm::floor(c);
    };
    const glm::dvec2 a = coord(glm::dvec2(123456.0, 98765.0));
    const glm::dvec2 b = coord(glm::dvec2(23456.0, 8765.0));
    for (int c = 0; c < 2; ++c) {
      const double d = std::abs(a[c] - b[c]);
      EXPECT_LT(std::min(d, 1.0 - d), 1e-6) << k;
    }
  }
}

TEST(WaveSlopes, LayersDriftDownTheWindAtTheirWavesSpeed) {
  for (int k = 0; k < kWaveLayers; ++k) {
    const WaveLayer l = wave_layer(k);
    // Deep water: c = sqrt(g L / 2 pi), L a fifth of the tile.
    EXPECT_NEAR(glm::length(l.velocity), std::sqrt(9.81 * l.tile_m / 5.0 / (2.0 * M_PI)), 1e-9);
    // A second later the pattern has moved by v: the phase by -v / tile.
    const glm::dvec2 p0 = wave_phase({10.0, 20.0}, {30.0, 30.0}, k, 0.0);
    const glm::dvec2 p1 = wave_phase({10.0, 20.0}, {30.0, 30.0}, k, 1.0);
    glm::dvec2 d = p1 - p0 + l.velocity / l.tile_m;
    d -= glm::round(d);
    EXPECT_LT(glm::length(d), 1e-9);
  }
  EXPECT_THROW(wave_layer(2), std::out_of_range);
}

}  // namespace
}  // namespace ig::water
