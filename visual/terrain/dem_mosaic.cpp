#include "terrain/dem_mosaic.h"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_vsi.h>
#include <gdal.h>
#include <gdal_utils.h>
#include <gdalwarper.h>
#include <ogr_srs_api.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>

#include "terrain/dem_loader.h"
#include "terrain/gdal_support.h"

namespace ig::terrain {
namespace {

namespace fs = std::filesystem;

using gdal::Dataset;
using gdal::handle;
using gdal::last_error;
using gdal::number_arg;

constexpr const char* kUnreadable = "not a recognised raster format";

// A warped VRT of `tile` in `wkt` on the grid of the first tile (origin
// `grid` [0], [3], pixel size [1], [5]): the tile's reprojected extent
// snapped outward to that grid's lines, so the mosaic keeps the first
// tile's samples where they are.
std::string warp_onto_grid(GDALDatasetH tile, const std::string& from_wkt, const std::string& wkt, const double grid[6],
                           const std::string& out) {
  Dataset probe(GDALAutoCreateWarpedVRT(tile, from_wkt.c_str(), wkt.c_str(), GRA_Bilinear, 0.125, nullptr));
  if (!probe) return last_error("no transformation between the CRSs");
  double gt[6];
  GDALGetGeoTransform(handle(probe), gt);
  const double w = GDALGetRasterXSize(handle(probe)), h = GDALGetRasterYSize(handle(probe));
  const double rx = grid[1], ry = std::fabs(grid[5]);
  auto snap_down = [](double v, double o, double r) { return o + std::floor((v - o) / r) * r; };
  auto snap_up = [](double v, double o, double r) { return o + std::ceil((v - o) / r) * r; };
  const double x0 = snap_down(std::min(gt[0], gt[0] + w * gt[1]), grid[0], rx);
  const double x1 = snap_up(std::max(gt[0], gt[0] + w * gt[1]), grid[0], rx);
  const double y0 = snap_down(std::min(gt[3], gt[3] + h * gt[5]), grid[3], ry);
  const double y1 = snap_up(std::max(gt[3], gt[3] + h * gt[5]), grid[3], ry);
  const Dataset warped =
      gdal::warp(tile, out, {"-of", "VRT", "-t_srs", wkt, "-r", "bilinear", "-te", number_arg(x0), number_arg(y0),
                             number_arg(x1), number_arg(y1), "-tr", number_arg(rx), number_arg(ry), "-dstnodata",
                             "-32768"});
  return warped ? std::string() : last_error("warp failed");
}

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string unique_memory_name(const char* what) {
  static std::atomic<int> counter{0};
  return "/vsimem/ig_mosaic_" + std::to_string(counter++) + "_" + what + ".vrt";
}

std::string wkt_of(OGRSpatialReferenceH srs) {
  char* wkt = nullptr;
  std::string out;
  if (srs && OSRExportToWkt(srs, &wkt) == OGRERR_NONE && wkt) out = wkt;
  CPLFree(wkt);
  return out;
}

}  // namespace

const std::vector<std::string>& dem_tile_extensions() {
  static const std::vector<std::string> ext = {".tif", ".tiff", ".hgt", ".asc", ".dem", ".img", ".vrt",
                                               ".bil", ".flt",  ".dt0", ".dt1", ".dt2", ".ter", ".nc"};
  return ext;
}

DemMosaic::DemMosaic(const std::string& folder) {
  gdal::register_once();
  gdal::QuietErrors quiet;
  std::error_code ec;
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(folder, ec))
    if (entry.is_regular_file(ec)) files.push_back(entry.path());
  if (ec) throw DemError(folder, "cannot list the folder: " + ec.message());
  std::sort(files.begin(), files.end());

  const auto& ext = dem_tile_extensions();
  std::string first_wkt;
  double first_gt[6] = {0, 1, 0, 0, 0, -1};
  for (const auto& f : files) {
    if (std::find(ext.begin(), ext.end(), lower(f.extension().string())) == ext.end()) {
      ignored_.push_back(f.filename().string());
      continue;
    }
    const std::string path = f.string();
    CPLErrorReset();
    Dataset ds(GDALOpenEx(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
    if (!ds) throw DemError(path, std::string("tile cannot be read: ") + last_error(kUnreadable));
    GDALDatasetH h = handle(ds);
    if (GDALGetRasterCount(h) != 1)
      throw DemError(path, "tile has " + std::to_string(GDALGetRasterCount(h)) +
                               " raster bands; a DEM tile must have exactly one");
    double gt[6];
    if (GDALGetGeoTransform(h, gt) != CE_None)
      throw DemError(path, "tile has no georeferencing, so it cannot be placed in a mosaic");
    const std::string wkt = wkt_of(GDALGetSpatialRef(h));
    std::string source = path;
    if (tiles_.empty()) {
      first_wkt = wkt;
      std::copy(gt, gt + 6, first_gt);
    } else if (wkt.empty() != first_wkt.empty()) {
      throw DemError(path, "tile " + std::string(wkt.empty() ? "has no" : "has a") + " CRS but the first tile (" +
                               tiles_.front() + ") " + (first_wkt.empty() ? "has none" : "has one"));
    } else if (!wkt.empty()) {
      OGRSpatialReferenceH a = OSRNewSpatialReference(wkt.c_str()), b = OSRNewSpatialReference(first_wkt.c_str());
      const bool same = a && b && OSRIsSame(a, b);
      OSRDestroySpatialReference(a);
      OSRDestroySpatialReference(b);
      if (!same) {  // reproject onto the first tile's CRS and grid
        source = unique_memory_name("warped");
        const std::string err = warp_onto_grid(h, wkt, first_wkt, first_gt, source);
        if (!err.empty()) throw DemError(path, "tile cannot be reprojected to the first tile's CRS: " + err);
        memory_files_.push_back(source);
        ++reprojected_;
      }
    }
    tiles_.push_back(path);
    sources_for_vrt_.push_back(source);
  }
  if (tiles_.empty())
    throw DemError(folder, "no DEM tiles in the folder (" + std::to_string(files.size()) +
                               " files, none with a DEM extension such as .tif, .hgt, .asc, .vrt)");

  // The mosaic: the finest resolution of any tile, bilinear where a tile is
  // coarser, -32768 (the SRTM void) where no tile covers.
  std::vector<const char*> names;
  for (const auto& s : sources_for_vrt_) names.push_back(s.c_str());
  const char* argv[] = {"-resolution", "highest", "-r", "bilinear", "-vrtnodata", "-32768", nullptr};
  GDALBuildVRTOptions* options = GDALBuildVRTOptionsNew(const_cast<char**>(argv), nullptr);
  if (!options) throw DemError(folder, "GDAL rejected the mosaic options: " + last_error("unknown option"));
  vrt_path_ = unique_memory_name("mosaic");
  CPLErrorReset();
  int usage_error = 0;
  Dataset vrt(GDALBuildVRT(vrt_path_.c_str(), int(names.size()), nullptr, names.data(), options, &usage_error));
  GDALBuildVRTOptionsFree(options);
  if (!vrt) throw DemError(folder, std::string("tiles cannot be mosaicked: ") + last_error(kUnreadable));
  memory_files_.push_back(vrt_path_);
}

DemMosaic::~DemMosaic() {
  for (const auto& f : memory_files_) VSIUnlink(f.c_str());
}

}  // namespace ig::terrain
