// Test imagery for the imagery-window tests (tests/cli/imagery_window.cmake),
// made at test time so nothing large is committed:
//   imagery_tool make DEM OUT.tif SCALE [OFFSET_DEG]
//     an RGB GeoTIFF over the DEM's extent (moved east by OFFSET_DEG), SCALE
//     times finer: red the height, green and blue a pixel-level pattern (so a
//     misplaced or resampled pixel shows).
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

int make(const char* dem_path, const char* out_path, int scale, double offset_deg) {
  GDALDatasetH dem = GDALOpen(dem_path, GA_ReadOnly);
  if (!dem) return std::fprintf(stderr, "cannot open %s\n", dem_path), 1;
  const int w = GDALGetRasterXSize(dem) * scale, h = GDALGetRasterYSize(dem) * scale;
  std::vector<float> z(std::size_t(w) * h);
  // GDAL resamples the DEM to the finer buffer (nearest).
  if (GDALRasterIO(GDALGetRasterBand(dem, 1), GF_Read, 0, 0, GDALGetRasterXSize(dem), GDALGetRasterYSize(dem),
                   z.data(), w, h, GDT_Float32, 0, 0) != CE_None)
    return std::fprintf(stderr, "cannot read %s\n", dem_path), 1;
  double gt[6];
  GDALGetGeoTransform(dem, gt);
  gt[0] += offset_deg;
  gt[1] /= scale;
  gt[2] /= scale;
  gt[4] /= scale;
  gt[5] /= scale;
  const auto [lo, hi] = std::minmax_element(z.begin(), z.end());
  const float span = std::max(*hi - *lo, 1.0f);
  std::vector<std::uint8_t> rgb(z.size() * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t p = std::size_t(y) * w + x;
      rgb[p] = std::uint8_t((z[p] - *lo) / span * 255.0f);
      rgb[p + z.size()] = std::uint8_t((x * 37 + y * 91) & 255);
      rgb[p + 2 * z.size()] = std::uint8_t(((x / 3 + y / 3) & 1) ? 220 : 40);
    }
  const char* options[] = {"TILED=YES", nullptr};
  GDALDatasetH out = GDALCreate(GDALGetDriverByName("GTiff"), out_path, w, h, 3, GDT_Byte, const_cast<char**>(options));
  if (!out) return std::fprintf(stderr, "cannot write %s\n", out_path), 1;
  GDALSetGeoTransform(out, gt);
  GDALSetSpatialRef(out, GDALGetSpatialRef(dem));
  const int bands[3] = {1, 2, 3};
  const CPLErr err = GDALDatasetRasterIO(out, GF_Write, 0, 0, w, h, rgb.data(), w, h, GDT_Byte, 3,
                                         const_cast<int*>(bands), 0, 0, 0);
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
  GDALDatasetRasterIO(ds, GF_Read, 0, 0, w, h, px.data(), w, h, GDT_Byte, bands, nullptr, 0, 0, 0);
  GDALClose(ds);
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
  if (cmd == "make" && argc >= 5) return make(argv[2], argv[3], std::atoi(argv[4]), argc > 5 ? std::atof(argv[5]) : 0.0);
  if (cmd == "diff" && argc == 4) return diff(argv[2], argv[3]);
  std::fprintf(stderr, "usage: imagery_tool make DEM OUT.tif SCALE [OFFSET_DEG] | diff A.png B.png\n");
  return 2;
}
