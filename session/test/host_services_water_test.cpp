// Host services over water: HAT/HOT Extended and LOS Extended responses,
// collision-style segments and native answers carry the water's material
// code and its level; land never does. On the generated water test terrain
// always, and on the real tiles of $IG_DEM_DIR (Suruga Bay, Lake Tahoe, Mono
// Lake; Death Valley and Owens Lake dry).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <variant>

#include "io/wire/cigi.h"
#include "io/wire/cigi_queries.h"
#include "io/wire/native_query.h"
#include "session/host_services.h"
#include "session/scene_setup.h"
#include "terrain/dem_loader.h"
#include "terrain/georef.h"
#include "terrain/surface_material.h"
#include "water/test/water_test_terrain.h"
#include "water/water_setup.h"

namespace {

using namespace ig::io::wire;
using ig::session::HostServices;
constexpr std::uint32_t kWater = std::uint32_t(ig::terrain::SurfaceMaterial::Water);
constexpr std::uint32_t kLand = std::uint32_t(ig::terrain::SurfaceMaterial::Land);

ig::io::Pose still() {
  ig::io::Pose p;
  p.position = {0.0, 0.0, 5000.0};
  return p;
}

// The Extended HAT/HOT and LOS answers at (lat, lon), as decoded from the
// wire (the response packets the IG sends, both byte orders).
struct Answers {
  HatHotResponse hot;
  LosResponse los;  // straight down from 600 m above the point's surface
};
Answers ask(HostServices& services, double lat, double lon, double alt, bool swap) {
  HatHotRequest h;
  h.id = 1;
  h.type = HatHotType::Extended;
  h.point = {lat, lon, alt};
  LosVectorRequest v;
  v.id = 2;
  v.extended = true;
  v.elevation_deg = -90.0f;
  v.max_range_m = 5000.0f;
  v.source = {lat, lon, alt};
  std::vector<std::uint8_t> d = encode_cigi_host_datagram(1, kCigiModeOperate, {}, swap);
  const auto hp = encode_cigi_hat_hot_request(h, swap);
  const auto vp = encode_cigi_los_vector_request(v, swap);
  d.insert(d.end(), hp.begin(), hp.end());
  d.insert(d.end(), vp.begin(), vp.end());
  services.take(d);
  // The IG's datagram back, decoded as a host reads it.
  const auto decoded = decode_cigi_responses(services.frame_datagram(encode_cigi_start_of_frame(1, 1, 0, kCigiModeOperate, false), still()));
  Answers a;
  EXPECT_TRUE(decoded && decoded->size() == 2u);
  if (decoded && decoded->size() == 2) {
    a.hot = std::get<HatHotResponse>((*decoded)[0]);
    a.los = std::get<LosResponse>((*decoded)[1]);
  }
  return a;
}

TEST(HostServicesWater, TheWaterTestTerrainsLakeAndLand) {
  ig::water::test::TestFeatures f;
  ig::terrain::Heightfield hf = ig::water::test::make_water_test_terrain(200, 150, f);
  ig::water::place_water(hf, {});
  ASSERT_TRUE(hf.water);
  HostServices services(hf, 0.0, ig::session::geodetic_placer(hf), ig::session::local_to_geodetic(hf));
  const auto to_geo = ig::session::local_to_geodetic(hf);
  const glm::dvec3 lake = *to_geo({f.lake_i * hf.spacing_x_m, f.lake_j * hf.spacing_y_m, 0.0});
  const glm::dvec3 land = *to_geo({150.5 * hf.spacing_x_m, 100.5 * hf.spacing_y_m, 0.0});
  for (bool swap : {false, true}) {
    const Answers w = ask(services, lake.x, lake.y, ig::water::test::kLakeLevel + 600.0, swap);
    EXPECT_TRUE(w.hot.valid);
    EXPECT_EQ(w.hot.material, kWater);
    EXPECT_NEAR(w.hot.hot_m, ig::water::test::kLakeLevel, 1e-6);
    EXPECT_NEAR(w.hot.normal_elevation_deg, 90.0f, 1e-4);
    EXPECT_TRUE(w.los.valid && w.los.range_valid);
    EXPECT_EQ(w.los.material, kWater);
    EXPECT_NEAR(w.los.range_m, 600.0, 1e-3);
    const Answers l = ask(services, land.x, land.y, 3000.0, swap);
    EXPECT_EQ(l.hot.material, kLand);
    EXPECT_EQ(l.los.material, kLand);
  }
  // The native protocol says the same.
  NativeQuery q;
  q.kind = NativeQueryKind::Height;
  q.geodetic = true;
  q.a = {lake.x, lake.y, 2000.0};
  const auto answer = decode_native_answer(encode_native_answer(services.answer(q)));
  ASSERT_TRUE(answer);
  EXPECT_EQ(answer->material, kWater);
  EXPECT_NEAR(answer->hot_or_range_m, ig::water::test::kLakeLevel, 1e-6);
  q.a = {land.x, land.y, 2000.0};
  EXPECT_EQ(decode_native_answer(encode_native_answer(services.answer(q)))->material, kLand);
}

const char* dem_dir() {
  const char* d = std::getenv("IG_DEM_DIR");
  return (d && *d) ? d : nullptr;
}

ig::terrain::Heightfield load_with_water(const std::string& name) {
  ig::terrain::Heightfield hf = ig::terrain::load_dem((std::filesystem::path(dem_dir()) / name).string());
  ig::water::place_water(hf, {});
  return hf;
}

TEST(HostServicesWater, BayLakesAndDryPlacesOnTheRealTiles) {
  if (!dem_dir()) GTEST_SKIP() << "IG_DEM_DIR not set: real-DEM tests skipped";
  struct Place {
    double lat, lon;
    bool water;
    double level;
  };
  const ig::terrain::Heightfield fuji = load_with_water("mt_fuji_90m.tif");
  const ig::terrain::Heightfield sierra = load_with_water("sierra_nevada_3arcsec_4097.tif");
  const std::vector<std::pair<const ig::terrain::Heightfield*, std::vector<Place>>> cases = {
      {&fuji,
       {{35.02, 138.60, true, 0.0}, {35.05, 138.65, true, 0.0}, {35.08, 138.80, true, 0.0},  // Suruga Bay
        {35.3606, 138.7274, false, 0.0}, {35.662, 138.568, false, 0.0}}},                    // Fuji, Kofu
      {&sierra,
       {{39.09, -120.04, true, 1899.0}, {39.15, -120.00, true, 1899.0},   // Lake Tahoe
        {37.96, -119.05, true, 1943.0}, {37.99, -118.95, true, 1943.0},   // Mono Lake
        {36.45, -117.93, false, 0.0}, {36.40, -117.98, false, 0.0},       // Owens Lake's dry bed
        {36.55, -117.05, false, 0.0}, {36.60, -117.10, false, 0.0},       // Death Valley, below sea level
        {36.70, -118.06, false, 0.0}}}};                                 // Owens Valley
  for (const auto& [hf, places] : cases) {
    HostServices services(*hf, 0.0, ig::session::geodetic_placer(*hf), ig::session::local_to_geodetic(*hf));
    for (const Place& p : places) {
      const Answers a = ask(services, p.lat, p.lon, 4500.0, false);
      ASSERT_TRUE(a.hot.valid) << p.lat << "," << p.lon;
      EXPECT_EQ(a.hot.material, p.water ? kWater : kLand) << p.lat << "," << p.lon;
      EXPECT_EQ(a.los.material, p.water ? kWater : kLand) << p.lat << "," << p.lon;
      if (p.water) {
        EXPECT_NEAR(a.hot.hot_m, p.level, 0.5) << p.lat << "," << p.lon;
      }
    }
  }
}

}  // namespace
