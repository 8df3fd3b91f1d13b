// Test imagery for the imagery-window tests (tests/cli/imagery_window.cmake),
// made at test time so nothing large is committed:
//   imagery_tool make DEM OUT.tif SCALE [OFFSET_DEG [compress]]
//     an RGB GeoTIFF over the DEM's extent (moved east by OFFSET_DEG), SCALE
//     times finer: red the height, green and blue a pixel-level pattern (so a
//     misplaced or resampled pixel shows); tiled, DEFLATE with `compress`.
//     Written in strips, so any size fits in little memory (the issue 16
//     benchmark, tools/bench/big_terrain.py, makes 24582^2 with it).
//   imagery_tool diff A.png B.png
//     prints "max M differing N of T over8 K" (largest channel difference,
//     pixels that differ at all, pixels, pixels that differ by more than 8).
#include <gdal.h>
#include <ogr_srs_api.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

int make(const char* dem_path, const char* out_path, int scale, double offset_deg, bool compress) {
  GDALDatasetH dem = GDALOpen(dem_path, GA_ReadOnly);
  if (!dem) return std::fprintf(stderr, "cannot open %s\n", dem_path), 1;
  const int dw = GDALGetRasterXSize(dem), dh = GDALGetRasterYSize(dem);
  const int w = dw * scale, h = dh * scale;
  GDALRasterBandH band = GDALGetRasterBand(dem, 1);
  double minmax[2];
  if (GDALComputeRasterMinMax(band, FALSE, minmax) != CE_None) return std::fprintf(stderr, "cannot read %s\n", dem_path), 1;
  const float lo = float(minmax[0]), span = std::max(float(minmax[1] - minmax[0]), 1.0f);
  double gt[6];
  GDALGetGeoTransform(dem, gt);
  gt[0] += offset_deg;
  gt[1] /= scale;
  gt[2] /= scale;
  gt[4] /= scale;
  gt[5] /= scale;
  const char* plain[] = {"TILED=YES", nullptr};
  const char* packed[] = {"TILED=YES", "COMPRESS=DEFLATE", "PREDICTOR=2", "BIGTIFF=IF_SAFER", nullptr};
  GDALDatasetH out = GDALCreate(GDALGetDriverByName("GTiff"), out_path, w, h, 3, GDT_Byte,
                                const_cast<char**>(compress ? packed : plain));
  if (!out) return std::fprintf(stderr, "cannot write %s\n", out_path), 1;
  GDALSetGeoTransform(out, gt);
  GDALSetSpatialRef(out, GDALGetSpatialRef(dem));
  // In strips of 64 DEM rows (any size of output in little memory); GDAL
  // resamples the DEM rows to the finer strip (nearest: sample x / scale).
  const int strip_dem = 64;
  std::vector<float> z;
  std::vector<std::uint8_t> rgb;
  CPLErr err = CE_None;
  for (int dy = 0; dy < dh && err == CE_None; dy += strip_dem) {
    const int rows_dem = std::min(strip_dem, dh - dy), y0 = dy * scale, rows = rows_dem * scale;
    z.resize(std::size_t(w) * rows);
    if (GDALRasterIO(band, GF_Read, 0, dy, dw, rows_dem, z.data(), w, rows, GDT_Float32, 0, 0) != CE_None)
      return std::fprintf(stderr, "cannot read %s\n", dem_path), 1;
    const std::size_t plane = z.size();
    rgb.resize(plane * 3);
    for (int r = 0; r < rows; ++r)
      for (int x = 0; x < w; ++x) {
        const std::size_t p = std::size_t(r) * w + x;
        const int y = y0 + r;
        rgb[p] = std::uint8_t((z[p] - lo) / span * 255.0f);
        rgb[p + plane] = std::uint8_t((x * 37 + y * 91) & 255);
        rgb[p + 2 * plane] = std::uint8_t(((x / 3 + y / 3) & 1) ? 220 : 40);
      }
    const int bands[3] = {1, 2, 3};
    err = GDALDatasetRasterIO(out, GF_Write, 0, y0, w, rows, rgb.data(), w, rows, GDT_Byte, 3, const_cast<int*>(bands),
                              0, 0, 0);
  }
  GDALClose(out);
  GDALClose(dem);
  return err == CE_None ? 0 : 1;
}

std::vector<std::uint8_t> read_png(const char* path, int& w, int& h, int& bands) {
  GDALDatasetH ds = GDALOpen(path, GA_ReadOnly);
  if (!ds) return {};
  w = GDALGetRasterXSize(ds);
  h = GDALGetRasterYSize(ds);
  bands = GDALGetRasterCount(ds);
  std::vector<std::uint8_t> px(std::size_t(w) * h * bands);
  const CPLErr err = GDALDatasetRasterIO(ds, GF_Read, 0, 0, w, h, px.data(), w, h, GDT_Byte, bands, nullptr, 0, 0, 0);
  GDALClose(ds);
  if (err != CE_None) {
    std::fprintf(stderr, "%s: %s\n", path, CPLGetLastErrorMsg());
    return {};
  }
  return px;
}

int diff(const char* a_path, const char* b_path) {
  int aw = 0, ah = 0, ab = 0, bw = 0, bh = 0, bb = 0;
  const auto a = read_png(a_path, aw, ah, ab), b = read_png(b_path, bw, bh, bb);
  if (a.empty() || a.size() != b.size() || aw != bw) return std::fprintf(stderr, "images differ in size\n"), 1;
  int worst = 0;
  long long differing = 0, over8 = 0;
  const std::size_t plane = std::size_t(aw) * ah;
  for (std::size_t p = 0; p < plane; ++p) {
    int d = 0;
    for (int c = 0; c < ab; ++c) d = std::max(d, std::abs(int(a[c * plane + p]) - int(b[c * plane + p])));
    worst = std::max(worst, d);
    differing += d > 0;
    over8 += d > 8;
  }
  std::printf("max %d differing %lld of %zu over8 %lld\n", worst, differing, plane, over8);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  GDALAllRegister();
  const std::string cmd = argc > 1 ? argv[1] : "";
  if (cmd == "make" && argc >= 5)
    return make(argv[2], argv[3], std::atoi(argv[4]), argc > 5 ? std::atof(argv[5]) : 0.0,
                argc > 6 && std::string(argv[6]) == "compress");
  if (cmd == "diff" && argc == 4) return diff(argv[2], argv[3]);
  std::fprintf(stderr, "usage: imagery_tool make DEM OUT.tif SCALE [OFFSET_DEG [compress]] | diff A.png B.png\n");
  return 2;
}
