// Synthetic terrain: determinism, parameter validation, range and shape.

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "terrain/synthetic_terrain.h"

using ig::terrain::generate_synthetic_terrain;
using ig::terrain::Heightfield;
using ig::options::SyntheticTerrainOptions;

namespace {

SyntheticTerrainOptions params(int size, unsigned seed) {
  SyntheticTerrainOptions p;
  p.size = size;
  p.seed = seed;
  return p;
}

// FNV-1a over the raw bytes of the heights.
std::uint64_t fingerprint(const Heightfield& hf) {
  std::uint64_t h = 14695981039346656037ull;
  const auto* b = reinterpret_cast<const unsigned char*>(hf.heights.data());
  for (std::size_t k = 0; k < hf.heights.size() * sizeof(float); ++k) {
    h ^= b[k];
    h *= 1099511628211ull;
  }
  return h;
}

double stddev(const Heightfield& hf) {
  double s = 0;
  for (float v : hf.heights) s += (v - hf.mean_m) * (v - hf.mean_m);
  return std::sqrt(s / double(hf.heights.size()));
}

void expect_invalid(const SyntheticTerrainOptions& p, const std::string& needle) {
  try {
    (void)generate_synthetic_terrain(p);
    ADD_FAILURE() << "accepted: " << needle;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

TEST(SyntheticTerrain, BitIdenticalAcrossRuns) {
  const Heightfield a = generate_synthetic_terrain(params(257, 42));
  const Heightfield b = generate_synthetic_terrain(params(257, 42));
  ASSERT_EQ(a.heights.size(), b.heights.size());
  EXPECT_EQ(std::memcmp(a.heights.data(), b.heights.data(), a.heights.size() * sizeof(float)), 0);
  EXPECT_EQ(a.mean_m, b.mean_m);
}

TEST(SyntheticTerrain, GoldenFingerprint) {
  // Pins the exact output across processes and builds. Uses only integer
  // hashing and + - * / floor in a fixed order. If the generator is changed
  // on purpose, update this value (and say so in the commit).
  const Heightfield hf = generate_synthetic_terrain(params(65, 1));
  EXPECT_EQ(fingerprint(hf), 0x0cfcaa74326a872bull) << "fingerprint 0x" << std::hex << fingerprint(hf);
}

TEST(SyntheticTerrain, DifferentSeedsDiffer) {
  const Heightfield a = generate_synthetic_terrain(params(129, 1));
  const Heightfield b = generate_synthetic_terrain(params(129, 2));
  std::size_t same = 0;
  for (std::size_t k = 0; k < a.heights.size(); ++k) same += a.heights[k] == b.heights[k];
  EXPECT_LT(same, a.heights.size() / 20);
}

TEST(SyntheticTerrain, SizeValidation) {
  for (int bad : {-1, 0, 1, 2, 4, 6, 100, 1000, 1024, 1026, 16386, 32769}) {
    SCOPED_TRACE(bad);
    expect_invalid(params(bad, 1), "size " + std::to_string(bad));
  }
  for (int ok : {3, 5, 9, 17, 33, 65}) {
    const Heightfield hf = generate_synthetic_terrain(params(ok, 1));
    EXPECT_EQ(hf.width, ok);
    EXPECT_EQ(hf.height, ok);
    EXPECT_EQ(hf.heights.size(), std::size_t(ok) * ok);
  }
}

TEST(SyntheticTerrain, OtherParameterValidation) {
  auto p = params(33, 1);
  p.octaves = 0;
  expect_invalid(p, "octaves 0");
  p = params(33, 1);
  p.spacing_m = 0;
  expect_invalid(p, "spacing_m");
  p = params(33, 1);
  p.relief_m = -5;
  expect_invalid(p, "relief_m");
  p = params(33, 1);
  p.ridge_weight = 1.5;
  expect_invalid(p, "ridge_weight");
  p = params(33, 1);
  p.base_m = std::numeric_limits<double>::quiet_NaN();
  expect_invalid(p, "base_m");
}

TEST(SyntheticTerrain, RangeMetadataAndNoNan) {
  SyntheticTerrainOptions p = params(257, 7);
  p.base_m = 250.0;
  p.relief_m = 2000.0;
  p.spacing_m = 20.0;
  const Heightfield hf = generate_synthetic_terrain(p);
  for (float v : hf.heights) {
    ASSERT_TRUE(std::isfinite(v));
    ASSERT_GE(v, 250.0f);
    ASSERT_LE(v, 2250.0f);
  }
  EXPECT_FLOAT_EQ(hf.min_m, 250.0f);  // normalised: spans the whole range
  EXPECT_FLOAT_EQ(hf.max_m, 2250.0f);
  EXPECT_EQ(hf.spacing_x_m, 20.0);
  EXPECT_EQ(hf.spacing_y_m, 20.0);
  EXPECT_EQ(hf.nodata_count, 0);
  EXPECT_FALSE(hf.georef);
  EXPECT_EQ(hf.source, "synthetic(seed=7,size=257)");
}

TEST(SyntheticTerrain, NotFlatAndNotNoise) {
  for (double ridge : {0.0, 0.5, 1.0}) {
    SCOPED_TRACE(ridge);
    SyntheticTerrainOptions p = params(513, 3);
    p.ridge_weight = ridge;
    const Heightfield hf = generate_synthetic_terrain(p);
    // Not flat: a real spread of heights.
    EXPECT_GT(stddev(hf), 0.08 * p.relief_m);
    // Neither flat nor white noise: neighbours differ, but by a small part of
    // the relief (smooth at the sample scale), and the surface is strongly
    // autocorrelated.
    double sum_abs = 0, max_abs = 0, cov = 0;
    std::size_t n = 0;
    for (int j = 0; j < hf.height; ++j)
      for (int i = 0; i + 1 < hf.width; ++i) {
        const double d = double(hf.at(i + 1, j)) - hf.at(i, j);
        sum_abs += std::fabs(d);
        max_abs = std::max(max_abs, std::fabs(d));
        cov += (hf.at(i + 1, j) - hf.mean_m) * (hf.at(i, j) - hf.mean_m);
        ++n;
      }
    const double mean_abs = sum_abs / double(n);
    const double var = stddev(hf) * stddev(hf);
    EXPECT_GT(mean_abs, 0.05);                  // metres
    EXPECT_LT(mean_abs, 0.02 * p.relief_m);     // < 30 m per 30 m step on average
    EXPECT_LT(max_abs, 0.25 * p.relief_m);      // no cliffs of a quarter of the relief
    EXPECT_GT(cov / double(n) / var, 0.95);     // lag-1 autocorrelation
  }
}

TEST(SyntheticTerrain, SmallerSizeIsTheSameLandscapeCoarser) {
  const Heightfield fine = generate_synthetic_terrain(params(513, 5));
  const Heightfield coarse = generate_synthetic_terrain(params(129, 5));
  // Correlate coarse(i, j) with fine(4i, 4j).
  double sa = 0, sb = 0, sab = 0, saa = 0, sbb = 0;
  const double n = double(coarse.heights.size());
  for (int j = 0; j < coarse.height; ++j)
    for (int i = 0; i < coarse.width; ++i) {
      const double a = coarse.at(i, j), b = fine.at(4 * i, 4 * j);
      sa += a, sb += b, sab += a * b, saa += a * a, sbb += b * b;
    }
  const double r = (sab - sa * sb / n) / std::sqrt((saa - sa * sa / n) * (sbb - sb * sb / n));
  EXPECT_GT(r, 0.98);
}

TEST(SyntheticTerrain, DefaultSizeTiming) {
  const auto t0 = std::chrono::steady_clock::now();
  const Heightfield hf = generate_synthetic_terrain(SyntheticTerrainOptions{});
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(hf.width, 1025);
  RecordProperty("generate_1025_ms", std::to_string(ms));
  std::printf("generate_synthetic_terrain(1025^2): %.1f ms\n", ms);
}

}  // namespace
