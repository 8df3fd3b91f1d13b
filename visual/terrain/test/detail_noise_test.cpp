// The ground-detail texture's texels and the tile phase the shader's
// coordinate starts from (terrain/detail_noise.h); no GL.
#include <gtest/gtest.h>

#include <cmath>

#include "terrain/detail_noise.h"

namespace {

using ig::terrain::DetailNoise;
using ig::terrain::make_detail_noise;

double channel(const DetailNoise& n, int x, int y, int c) {
  x = ((x % n.size) + n.size) % n.size;
  y = ((y % n.size) + n.size) % n.size;
  return n.rgba[(std::size_t(y) * n.size + x) * 4 + c];
}

TEST(DetailNoise, SameSeedSameBytesOtherSeedOtherBytes) {
  EXPECT_EQ(make_detail_noise(64, 3).rgba, make_detail_noise(64, 3).rgba);
  EXPECT_NE(make_detail_noise(64, 3).rgba, make_detail_noise(64, 4).rgba);
}

TEST(DetailNoise, RefusesSizesThatAreNotPowersOfTwo) {
  EXPECT_THROW(make_detail_noise(100), std::invalid_argument);
  EXPECT_THROW(make_detail_noise(32), std::invalid_argument);
}

// Every channel is centred on 127.5, so the texture's top mip (what a far
// surface sees) leaves the material colour as it is, and none is flat.
TEST(DetailNoise, ChannelsAreCentredAndVary) {
  const DetailNoise n = make_detail_noise();
  for (int c = 0; c < 4; ++c) {
    double sum = 0.0, sq = 0.0;
    for (int y = 0; y < n.size; ++y)
      for (int x = 0; x < n.size; ++x) {
        const double v = channel(n, x, y, c);
        sum += v;
        sq += v * v;
      }
    const double count = double(n.size) * n.size, mean = sum / count;
    EXPECT_NEAR(mean, 127.5, 1.0) << "channel " << c;
    EXPECT_NEAR(std::sqrt(sq / count - mean * mean), 40.0, 2.0) << "channel " << c;
  }
}

// The texture repeats without a seam: the step across the wrap is no larger
// than steps inside the tile.
TEST(DetailNoise, TilesWithoutASeam) {
  const DetailNoise n = make_detail_noise();
  for (int c = 0; c < 4; ++c) {
    double inside = 0.0, across = 0.0;
    for (int y = 0; y < n.size; ++y) {
      inside = std::max(inside, std::fabs(channel(n, n.size / 2, y, c) - channel(n, n.size / 2 - 1, y, c)));
      across = std::max(across, std::fabs(channel(n, 0, y, c) - channel(n, n.size - 1, y, c)));
    }
    EXPECT_LE(across, inside * 1.5 + 2.0) << "channel " << c;
  }
}

// Grain sizes: neighbouring texels of the fine channel differ much more
// than those of the broad one (each serves its own scale).
TEST(DetailNoise, ChannelsHaveTheirOwnGrain) {
  const DetailNoise n = make_detail_noise();
  double step[4] = {0, 0, 0, 0};
  for (int c = 0; c < 4; ++c)
    for (int y = 0; y < n.size; ++y)
      for (int x = 0; x < n.size; ++x) step[c] += std::fabs(channel(n, x + 1, y, c) - channel(n, x, y, c));
  EXPECT_GT(step[0], 2.0 * step[1]);
  EXPECT_GT(step[1], 2.0 * step[2]);
  EXPECT_GT(step[2], 2.0 * step[3]);
}

// The shader's tile coordinate (s - anchor) * spacing / tile + phase(anchor)
// names the same texel whichever anchor the eye gives, even 30 000 samples
// from the DEM's origin, where a float product of the anchor would be off by
// a good part of a texel.
TEST(DetailNoise, TileCoordinateDoesNotDependOnTheAnchor) {
  const glm::dvec2 spacing(73.3, 92.6);
  const double tile = 87.3;
  const glm::dvec2 s(30123.25, 29871.75);  // a pixel's sample coordinate
  auto coordinate = [&](glm::dvec2 anchor) {
    const glm::dvec2 phase = ig::terrain::detail_tile_phase(anchor, spacing, tile);
    EXPECT_GE(phase.x, 0.0);
    EXPECT_LT(phase.x, 1.0);
    return (s - anchor) * spacing / tile + phase;
  };
  const glm::dvec2 a = coordinate({30123.0, 29871.0}), b = coordinate({30000.0, 29900.0}), c = coordinate({0.0, 0.0});
  for (const glm::dvec2& other : {b, c}) {
    const glm::dvec2 d = other - a;
    EXPECT_NEAR(d.x, std::round(d.x), 1e-6);
    EXPECT_NEAR(d.y, std::round(d.y), 1e-6);
  }
  // Near the anchor the coordinate is small: float keeps it to ~1e-7 tile.
  EXPECT_LT(std::fabs(a.x), 2.0);
  EXPECT_LT(std::fabs(a.y), 2.0);
}

}  // namespace
