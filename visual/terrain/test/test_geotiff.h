#pragma once
// A single-band Float32 GeoTIFF for the loader tests: EPSG:4326, samples
// 1/1200 degree apart from 119 W, 37.5 N, the given nodata value. Rows in
// file order (north first), or south first as a Heightfield holds them.

#include <cpl_conv.h>
#include <gdal.h>
#include <gtest/gtest.h>
#include <ogr_srs_api.h>

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

namespace ig::terrain::test {

inline void write_test_geotiff(const std::string& path, int w, int h, const std::vector<float>& north_first,
                               double nodata) {
  GDALAllRegister();
  GDALDatasetH ds = GDALCreate(GDALGetDriverByName("GTiff"), path.c_str(), w, h, 1, GDT_Float32, nullptr);
  ASSERT_NE(ds, nullptr) << path;
  double gt[6] = {-119.0, 1.0 / 1200, 0.0, 37.5, 0.0, -1.0 / 1200};
  GDALSetGeoTransform(ds, gt);
  OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
  OSRImportFromEPSG(srs, 4326);
  char* wkt = nullptr;
  OSRExportToWkt(srs, &wkt);
  GDALSetProjection(ds, wkt);
  CPLFree(wkt);
  OSRDestroySpatialReference(srs);
  GDALRasterBandH band = GDALGetRasterBand(ds, 1);
  GDALSetRasterNoDataValue(band, nodata);
  EXPECT_EQ(GDALRasterIO(band, GF_Write, 0, 0, w, h, const_cast<float*>(north_first.data()), w, h, GDT_Float32, 0, 0),
            CE_None);
  GDALClose(ds);
}

inline void write_south_first_geotiff(const std::string& path, int w, int h, const std::vector<float>& south_first,
                                      double nodata) {
  std::vector<float> north_first(south_first.size());
  for (int r = 0; r < h; ++r)
    std::copy_n(south_first.begin() + std::ptrdiff_t(h - 1 - r) * w, w, north_first.begin() + std::ptrdiff_t(r) * w);
  write_test_geotiff(path, w, h, north_first, nodata);
}

}  // namespace ig::terrain::test
