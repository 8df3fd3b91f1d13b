// Geodetic placement on georeferenced grids (terrain/georef.h).
#include <gtest/gtest.h>

#include <cmath>

#include "terrain/dem_loader.h"
#include "terrain/georef.h"

namespace {

ig::terrain::Heightfield grid_with_origin(double lat0, double lon0) {
  ig::terrain::Heightfield hf;
  hf.width = hf.height = 101;
  hf.spacing_x_m = hf.spacing_y_m = 30.0;
  hf.heights.assign(101 * 101, 0.0f);
  hf.georef = ig::terrain::make_geographic_georef(lat0, lon0, 30.0, 30.0);
  return hf;
}

TEST(Georef, OriginMapsToTheSouthWestSample) {
  const auto hf = grid_with_origin(46.5, 7.9);
  const auto p = ig::terrain::geodetic_to_local(hf, 46.5, 7.9);
  ASSERT_TRUE(p.has_value());
  EXPECT_NEAR(p->x, 0.0, 1e-6);
  EXPECT_NEAR(p->y, 0.0, 1e-6);
}

TEST(Georef, OneKilometreNorthAndEast) {
  const auto hf = grid_with_origin(46.5, 7.9);
  const auto m = ig::terrain::metres_per_angle(46.5);
  const auto p = ig::terrain::geodetic_to_local(hf, 46.5 + 1000.0 / m.north, 7.9 + 1000.0 / m.east);
  ASSERT_TRUE(p.has_value());
  EXPECT_NEAR(p->x, 1000.0, 1e-6);
  EXPECT_NEAR(p->y, 1000.0, 1e-6);
}

TEST(Georef, NoGeoreferenceMeansNoPlacement) {
  auto hf = grid_with_origin(46.5, 7.9);
  hf.georef.reset();
  EXPECT_FALSE(ig::terrain::geodetic_to_local(hf, 46.5, 7.9).has_value());
}

TEST(Georef, NonFiniteInputIsRejected) {
  const auto hf = grid_with_origin(46.5, 7.9);
  EXPECT_FALSE(ig::terrain::geodetic_to_local(hf, std::nan(""), 7.9).has_value());
}

}  // namespace
