#pragma once
// Test data for the imagery tests (terrain/test/imagery_loader_test.cpp,
// render/test/imagery_window_test.cpp): a small georeferenced DEM and RGB
// GeoTIFFs over it, coloured by place, written at test time.

#include <gtest/gtest.h>

#include <cpl_conv.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "terrain/heightfield.h"

namespace imagery_test {

// A 1/1200-degree DEM whose north-west sample centre is at (-118, 37).
constexpr double kRes = 1.0 / 1200.0;
inline ig::terrain::Heightfield dem(int w, int h) {
  ig::terrain::Heightfield hf;
  hf.width = w;
  hf.height = h;
  hf.heights.assign(std::size_t(w) * h, 100.0f);
  hf.spacing_x_m = 74.0;
  hf.spacing_y_m = 92.6;
  ig::terrain::GeoReference g;
  OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
  OSRImportFromEPSG(srs, 4326);
  char* wkt = nullptr;
  OSRExportToWkt(srs, &wkt);
  g.crs_wkt = wkt;
  CPLFree(wkt);
  OSRDestroySpatialReference(srs);
  g.geographic = true;
  // (i, j) with j = 0 south -> lon, lat of the sample centre.
  g.grid_to_crs = {-118.0, kRes, 0.0, 37.0 - (h - 1) * kRes, 0.0, kRes};
  hf.georef = g;
  hf.finalize_stats();
  return hf;
}

// Colour of a place: red by longitude, green by latitude, over a 0.1 degree square.
inline std::array<double, 2> colour_of(double lon, double lat) {
  return {(lon + 118.0) / 0.1 * 255.0, (lat - 36.9) / 0.1 * 255.0};
}

// Writes an RGB GeoTIFF of w x h pixels in EPSG:epsg with geotransform gt,
// each pixel coloured by colour_of its centre's lon/lat.
inline std::string write_image(const std::string& name, int epsg, const double gt[6], int w, int h, bool tiled = false) {
  GDALAllRegister();
  const std::string path = (std::filesystem::temp_directory_path() / name).string();
  const char* tiled_options[] = {"TILED=YES", "BLOCKXSIZE=32", "BLOCKYSIZE=32", "COMPRESS=DEFLATE", nullptr};
  GDALDatasetH ds = GDALCreate(GDALGetDriverByName("GTiff"), path.c_str(), w, h, 3, GDT_Byte,
                               tiled ? const_cast<char**>(tiled_options) : nullptr);
  GDALSetGeoTransform(ds, const_cast<double*>(gt));
  OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr), wgs = OSRNewSpatialReference(nullptr);
  OSRImportFromEPSG(srs, epsg);
  OSRImportFromEPSG(wgs, 4326);
  OSRSetAxisMappingStrategy(srs, OAMS_TRADITIONAL_GIS_ORDER);
  OSRSetAxisMappingStrategy(wgs, OAMS_TRADITIONAL_GIS_ORDER);
  GDALSetSpatialRef(ds, srs);
  OGRCoordinateTransformationH to_wgs = OCTNewCoordinateTransformation(srs, wgs);
  std::vector<std::uint8_t> r(std::size_t(w) * h), g(r.size()), b(r.size(), 60);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double px = gt[0] + (x + 0.5) * gt[1], py = gt[3] + (y + 0.5) * gt[5];
      OCTTransform(to_wgs, 1, &px, &py, nullptr);
      const auto c = colour_of(px, py);
      r[y * w + x] = std::uint8_t(std::clamp(c[0], 0.0, 255.0));
      g[y * w + x] = std::uint8_t(std::clamp(c[1], 0.0, 255.0));
    }
  for (int k = 0; k < 3; ++k)
    EXPECT_EQ(GDALRasterIO(GDALGetRasterBand(ds, k + 1), GF_Write, 0, 0, w, h, (k == 0 ? r : k == 1 ? g : b).data(), w,
                           h, GDT_Byte, 0, 0),
              CE_None);
  OCTDestroyCoordinateTransformation(to_wgs);
  OSRDestroySpatialReference(srs);
  OSRDestroySpatialReference(wgs);
  GDALClose(ds);
  return path;
}

}  // namespace imagery_test
