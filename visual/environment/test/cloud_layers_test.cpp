// The cloud layers' rules, the noise field they are cut from and the
// per-view values the cloud pass takes, without a GL context.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "environment/cloud_frame.h"
#include "environment/cloud_layers.h"
#include "environment/cloud_noise.h"

namespace {

using ig::environment::check_cloud_layer;
using ig::options::CloudLayer;
using ig::options::CloudType;

CloudLayer stratus() {
  CloudLayer l;
  l.type = CloudType::Stratus;
  l.coverage = 1.0;
  l.base_m = 1500.0;
  l.thickness_m = 300.0;
  return l;
}

TEST(CloudLayers, BadLayersAreRefusedWithTheReason) {
  struct Case {
    void (*change)(CloudLayer&);
    const char* why;
  };
  const Case cases[] = {
      {[](CloudLayer& l) { l.coverage = 1.01; }, "coverage outside 0-100 %"},
      {[](CloudLayer& l) { l.coverage = -0.01; }, "coverage outside 0-100 %"},
      {[](CloudLayer& l) { l.thickness_m = -1.0; }, "negative thickness"},
      {[](CloudLayer& l) { l.transition_m = -1.0; }, "negative transition band"},
      {[](CloudLayer& l) { l.visibility_m = -5.0; }, "negative visibility"},
      {[](CloudLayer& l) { l.scud = 2.0; }, "scud outside 0-100 %"},
      {[](CloudLayer& l) { l.base_m = 99900.0; }, "top above 100 km"},
      {[](CloudLayer& l) { l.base_m = std::numeric_limits<double>::quiet_NaN(); }, "a field is not a finite number"},
      {[](CloudLayer& l) { l.wind_mps.x = std::numeric_limits<double>::infinity(); }, "a field is not a finite number"},
      {[](CloudLayer& l) { l.base_m = -500.0; }, "entirely below the terrain"},
  };
  for (const auto& c : cases) {
    CloudLayer l = stratus();
    c.change(l);
    const auto check = check_cloud_layer(l, 0.0);
    EXPECT_FALSE(check.layer.has_value()) << c.why;
    EXPECT_EQ(check.refused, c.why);
  }
}

TEST(CloudLayers, ABaseBelowTheTerrainIsRaisedAndVisibilityDefaultsToTheType) {
  CloudLayer l = stratus();
  l.base_m = 100.0;  // terrain from 400 m: the layer's bottom 300 m are under it
  l.thickness_m = 1000.0;
  const auto check = check_cloud_layer(l, 400.0);
  ASSERT_TRUE(check.layer.has_value()) << check.refused;
  EXPECT_EQ(check.layer->base_m, 400.0);
  EXPECT_EQ(check.layer->thickness_m, 700.0);  // the top stays at 1 100 m
  EXPECT_EQ(check.layer->visibility_m, ig::environment::look_of(CloudType::Stratus).visibility_m);
  // Koschmieder: the extinction that leaves 2 % at the visibility.
  EXPECT_NEAR(std::exp(-ig::environment::extinction_per_m(*check.layer) * check.layer->visibility_m), 0.02, 1e-3);
  // Without a terrain to check against (the host's packets), nothing is raised.
  EXPECT_EQ(check_cloud_layer(l, -std::numeric_limits<double>::infinity()).layer->base_m, 100.0);
}

TEST(CloudLayers, EveryCigiTypeHasANameAndALook) {
  for (int v = 0; v < 16; ++v) {
    const auto t = ig::options::cloud_type_of_cigi(v);
    EXPECT_EQ(t.has_value(), v >= 1 && v <= 10) << v;
    if (!t) continue;
    EXPECT_EQ(ig::options::cloud_type_named(ig::options::cloud_type_name(*t)), t);
    EXPECT_GT(ig::environment::look_of(*t).element_m, 0.0);
  }
  EXPECT_EQ(ig::environment::look_of(CloudType::Cumulus).form, ig::environment::CloudForm::Cumuliform);
  EXPECT_EQ(ig::environment::look_of(CloudType::Nimbostratus).form, ig::environment::CloudForm::Stratiform);
  EXPECT_EQ(ig::environment::look_of(CloudType::Cirrus).form, ig::environment::CloudForm::Cirriform);
  EXPECT_FALSE(ig::options::cloud_type_named("fog").has_value());
}

TEST(CloudNoise, RankedSoACutLeavesExactlyTheCoverage) {
  const auto field = ig::environment::cloud_noise_field();
  const std::size_t n = field.size();
  ASSERT_EQ(n, std::size_t(ig::environment::kCloudNoiseSide) * ig::environment::kCloudNoiseSide);
  for (double coverage : {0.1, 0.25, 0.5, 0.9}) {
    const auto above = std::count_if(field.begin(), field.end(), [&](float v) { return v > 1.0 - coverage; });
    EXPECT_NEAR(double(above) / double(n), coverage, 1.0 / double(n) + 1e-9) << coverage;
  }
}

TEST(CloudNoise, TilesAndHasNoPatchFarFromTheCoverage) {
  const int side = ig::environment::kCloudNoiseSide;
  const auto f = ig::environment::cloud_noise_field();
  auto at = [&](int x, int y) { return f[std::size_t((y + side) % side) * side + std::size_t((x + side) % side)]; };
  // Across the wrap the field steps no more than it does inside.
  double inside = 0.0, across = 0.0;
  for (int y = 0; y < side; ++y) {
    inside = std::max(inside, double(std::abs(at(side / 2, y) - at(side / 2 - 1, y))));
    across = std::max(across, double(std::abs(at(0, y) - at(side - 1, y))));
  }
  EXPECT_LE(across, 2.0 * inside);
  // Any window of 6 x 6 elements (a view of cumulus straight up from 1.5 km)
  // is within 0.2 of a 50 % coverage.
  const int window = int(6 * ig::environment::kCloudNoiseElementTexels);
  double worst = 0.0;
  for (int y0 = 0; y0 < side; y0 += 16)
    for (int x0 = 0; x0 < side; x0 += 16) {
      int above = 0;
      for (int y = 0; y < window; ++y)
        for (int x = 0; x < window; ++x) above += at(x0 + x, y0 + y) > 0.5f;
      worst = std::max(worst, std::abs(double(above) / double(window * window) - 0.5));
    }
  std::printf("worst 6 x 6 element window: %.3f from 50 %%\n", worst);
  EXPECT_LT(worst, 0.2);
}

TEST(CloudFrame, LayersPackedWithTheEyeOnTheFieldAndTheWindsDrift) {
  CloudLayer cu = stratus();
  cu.type = CloudType::Cumulus;
  cu.coverage = 0.4;
  cu.id = 2;
  cu.wind_mps = {10.0, 0.0};
  CloudLayer none = stratus();
  none.coverage = 0.0;  // nothing to draw: left out
  const ig::environment::SkyLight sky;
  const auto a = ig::environment::cloud_frame({none, cu}, {1000.0, 2000.0, 500.0}, 0.0, sky);
  ASSERT_EQ(a.layers, 1);
  EXPECT_FLOAT_EQ(a.packed[0].x, 1500.0f);
  EXPECT_FLOAT_EQ(a.packed[0].y, 1800.0f);
  EXPECT_NEAR(a.packed[1].x, 1.0 - std::pow(0.4, 1.2), 1e-6);  // heaps: cut at 1 - coverage^1.2
  EXPECT_FLOAT_EQ(a.packed[1].y, 1.0f);  // cumuliform
  // 60 s of a 10 m/s wind moves the layer 600 m east: the eye 600 m further
  // east sees at t = 60 what it saw at t = 0.
  const auto b = ig::environment::cloud_frame({cu}, {1600.0, 2000.0, 500.0}, 60.0, sky);
  EXPECT_NEAR(a.packed[2].x, b.packed[2].x, 1e-5);
  EXPECT_NEAR(a.packed[2].y, b.packed[2].y, 1e-5);
  // However far the eye goes, its coordinate on the field stays in [0, 1).
  const auto far = ig::environment::cloud_frame({cu}, {3.0e7, -4.0e7, 500.0}, 1.0e6, sky);
  EXPECT_GE(far.packed[2].x, 0.0f);
  EXPECT_LT(far.packed[2].x, 1.0f);
  EXPECT_GE(far.packed[2].y, 0.0f);
  EXPECT_LT(far.packed[2].y, 1.0f);
  // Overcast: no cut at all.
  EXPECT_LT(ig::environment::cloud_frame({stratus()}, {0.0, 0.0, 0.0}, 0.0, sky).packed[1].x, 0.0f);
}

}  // namespace
