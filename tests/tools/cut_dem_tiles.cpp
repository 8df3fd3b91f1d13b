// Cuts a DEM into NX x NY GeoTIFF tiles (test data for folder mosaics, made
// at test time so nothing large is committed):
//   cut_dem_tiles IN.tif OUT_DIR NX NY [--skip K] [--epsg-of-last CODE]
// Tiles are tile_<row>_<col>.tif, row 0 at the north; they do not overlap.
// --skip K leaves tile K (row-major) out (a missing tile); --epsg-of-last
// writes the last tile reprojected to EPSG:CODE (a tile in another CRS).
#include <gdal.h>
#include <gdal_utils.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace {
int run(const std::vector<std::string>& argv, GDALDatasetH src, const std::string& out) {
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  int usage = 0;
  GDALDatasetH dst = nullptr;
  if (argv.front() == "-t_srs") {
    GDALWarpAppOptions* o = GDALWarpAppOptionsNew(args.data(), nullptr);
    dst = GDALWarp(out.c_str(), nullptr, 1, &src, o, &usage);
    GDALWarpAppOptionsFree(o);
  } else {
    GDALTranslateOptions* o = GDALTranslateOptionsNew(args.data(), nullptr);
    dst = GDALTranslate(out.c_str(), src, o, &usage);
    GDALTranslateOptionsFree(o);
  }
  if (!dst) {
    std::fprintf(stderr, "cut_dem_tiles: %s: %s\n", out.c_str(), CPLGetLastErrorMsg());
    return 1;
  }
  GDALClose(dst);
  return 0;
}
}  // namespace

int main(int argc, char** argv) {
  if (argc < 5) {
    std::fprintf(stderr, "usage: cut_dem_tiles IN OUT_DIR NX NY [--skip K] [--epsg-of-last CODE]\n");
    return 2;
  }
  const std::string in = argv[1], dir = argv[2];
  const int nx = std::atoi(argv[3]), ny = std::atoi(argv[4]);
  int skip = -1;
  std::string epsg;
  for (int k = 5; k + 1 < argc; k += 2) {
    const std::string f = argv[k];
    if (f == "--skip") skip = std::atoi(argv[k + 1]);
    else if (f == "--epsg-of-last") epsg = argv[k + 1];
  }
  GDALAllRegister();
  GDALDatasetH src = GDALOpen(in.c_str(), GA_ReadOnly);
  if (!src) {
    std::fprintf(stderr, "cut_dem_tiles: %s: cannot open\n", in.c_str());
    return 1;
  }
  std::filesystem::create_directories(dir);
  const int w = GDALGetRasterXSize(src), h = GDALGetRasterYSize(src);
  for (int r = 0; r < ny; ++r)
    for (int c = 0; c < nx; ++c) {
      const int k = r * nx + c;
      if (k == skip) continue;
      const int x0 = w * c / nx, x1 = w * (c + 1) / nx, y0 = h * r / ny, y1 = h * (r + 1) / ny;
      const std::string out = dir + "/tile_" + std::to_string(r) + "_" + std::to_string(c) + ".tif";
      const std::vector<std::string> window = {"-srcwin", std::to_string(x0), std::to_string(y0),
                                               std::to_string(x1 - x0), std::to_string(y1 - y0)};
      if (k == nx * ny - 1 && !epsg.empty()) {
        const std::string cut = out + ".cut.tif";
        if (run(window, src, cut)) return 1;
        GDALDatasetH piece = GDALOpen(cut.c_str(), GA_ReadOnly);
        const int rc = run({"-t_srs", "EPSG:" + epsg, "-r", "bilinear"}, piece, out);
        GDALClose(piece);
        std::filesystem::remove(cut);
        if (rc) return 1;
      } else if (run(window, src, out)) {
        return 1;
      }
    }
  GDALClose(src);
  return 0;
}
