// The big-terrain benchmark's synthetic DEM, made at bench time (nothing large is kept):
// the synthetic fractal (terrain/synthetic_terrain.h) at 16385^2, 30 m,
// refined 2x by Catmull-Rom interpolation to 32769^2 at 15 m, written as
// N x N GeoTIFF tiles (Int16 metres, deflate, tiled) that share their edge
// samples like SRTM tiles, in UTM zone 11N. A folder of them is what a user
// points terrain.file at (terrain/dem_mosaic.h mosaics it).
//   make_synthetic_tiles OUT_DIR [--tiles N] [--base-size S]
// N must divide S - 1 (default 8 and 16385: 64 tiles of 4097^2). Prints the
// DEM's size and where its centre is, in terrain-local metres.
#include <cpl_conv.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "terrain/synthetic_terrain.h"

namespace {

// Catmull-Rom weights for fraction t (0 or 0.5 here).
void weights(double t, double w[4]) {
  const double t2 = t * t, t3 = t2 * t;
  w[0] = 0.5 * (-t3 + 2 * t2 - t);
  w[1] = 0.5 * (3 * t3 - 5 * t2 + 2);
  w[2] = 0.5 * (-3 * t3 + 4 * t2 + t);
  w[3] = 0.5 * (t3 - t2);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: make_synthetic_tiles OUT_DIR [--tiles N] [--base-size S]\n");
    return 2;
  }
  const std::string out = argv[1];
  int tiles = 8, base_size = 16385;
  for (int a = 2; a + 1 < argc; a += 2) {
    const std::string k = argv[a];
    if (k == "--tiles") tiles = std::atoi(argv[a + 1]);
    else if (k == "--base-size") base_size = std::atoi(argv[a + 1]);
    else {
      std::fprintf(stderr, "make_synthetic_tiles: unknown option %s\n", k.c_str());
      return 2;
    }
  }
  if (tiles < 1 || (base_size - 1) % tiles != 0) {
    std::fprintf(stderr, "make_synthetic_tiles: --tiles %d must divide --base-size %d minus 1\n", tiles, base_size);
    return 2;
  }
  ig::options::SyntheticTerrainOptions p;
  p.size = base_size;
  p.spacing_m = 30.0;
  p.relief_m = 2500.0;
  const ig::terrain::Heightfield base = ig::terrain::generate_synthetic_terrain(p);  // validates the size
  const int n = 2 * (base_size - 1) + 1;  // samples a side after the 2x refinement
  const int t = (n - 1) / tiles;          // tile step; tiles are t + 1 samples (shared edges)
  const double spacing = p.spacing_m / 2, west = 300000.0, north = 4200000.0;

  GDALAllRegister();
  OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
  if (OSRImportFromEPSG(srs, 32611) != OGRERR_NONE) {
    std::fprintf(stderr, "make_synthetic_tiles: EPSG:32611 unknown to PROJ\n");
    return 1;
  }
  char* wkt = nullptr;
  OSRExportToWkt(srs, &wkt);
  std::filesystem::create_directories(out);
  // Refined sample (i, j) of the whole grid (row 0 south, as the Heightfield).
  auto refined = [&](int i, int j) {
    double wx[4], wy[4];
    weights(0.5 * (i & 1), wx);
    weights(0.5 * (j & 1), wy);
    const int bi = i / 2, bj = j / 2;
    double h = 0.0;
    for (int b = 0; b < 4; ++b)
      for (int a = 0; a < 4; ++a) h += wx[a] * wy[b] * base.at_clamped(bi - 1 + a, bj - 1 + b);
    return h;
  };
  char* options[] = {const_cast<char*>("TILED=YES"), const_cast<char*>("COMPRESS=DEFLATE"),
                     const_cast<char*>("PREDICTOR=2"), const_cast<char*>("ZLEVEL=1"), nullptr};
  std::vector<std::int16_t> rows(static_cast<std::size_t>(t + 1) * (t + 1));
  for (int ty = 0; ty < tiles; ++ty)
    for (int tx = 0; tx < tiles; ++tx) {
      // Tile (tx, ty) counted from the south-west; its file row 0 is its north edge.
      const int i0 = tx * t, j0 = ty * t;
      for (int r = 0; r <= t; ++r) {
        const int j = j0 + t - r;
        for (int c = 0; c <= t; ++c)
          rows[static_cast<std::size_t>(r) * (t + 1) + c] = std::int16_t(std::lround(refined(i0 + c, j)));
      }
      const std::string file = out + "/synthetic_r" + std::to_string(tiles - 1 - ty) + "_c" + std::to_string(tx) + ".tif";
      GDALDatasetH ds = GDALCreate(GDALGetDriverByName("GTiff"), file.c_str(), t + 1, t + 1, 1, GDT_Int16, options);
      if (!ds) {
        std::fprintf(stderr, "make_synthetic_tiles: cannot create %s\n", file.c_str());
        return 1;
      }
      // Pixel-is-area: sample (i, j) is the centre of its pixel.
      const double gt[6] = {west + (i0 - 0.5) * spacing, spacing, 0.0, north - ((n - 1 - (j0 + t)) - 0.5) * spacing, 0.0, -spacing};
      GDALSetGeoTransform(ds, const_cast<double*>(gt));
      GDALSetProjection(ds, wkt);
      const CPLErr err = GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Write, 0, 0, t + 1, t + 1, rows.data(), t + 1, t + 1,
                                      GDT_Int16, 0, 0);
      GDALClose(ds);
      if (err != CE_None) {
        std::fprintf(stderr, "make_synthetic_tiles: writing %s failed\n", file.c_str());
        return 1;
      }
    }
  CPLFree(wkt);
  OSRDestroySpatialReference(srs);
  std::printf("{\"width\": %d, \"height\": %d, \"spacing_m\": %g, \"tiles\": %d, \"centre_local_m\": [%g, %g]}\n", n, n,
              spacing, tiles * tiles, 0.5 * (n - 1) * spacing, 0.5 * (n - 1) * spacing);
  return 0;
}
