#include "terrain/geoid_correction.h"

#include <cpl_conv.h>
#include <cpl_string.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "terrain/gdal_support.h"

namespace ig::terrain {
namespace {

// Node k of a coarse axis over n samples: sample min(k * step, n - 1).
int node_sample(int k, int step, int n) { return std::min(k * step, n - 1); }

// Bilinear weights of sample coordinate s between the nodes around it.
void locate(double s, int step, int n, int nodes, int& k, double& t) {
  s = std::clamp(s, 0.0, double(n - 1));
  k = std::min(int(s / step), nodes - 2);
  const int a = node_sample(k, step, n), b = node_sample(k + 1, step, n);
  t = b > a ? (s - a) / (b - a) : 0.0;
}

}  // namespace

std::string GeoidCorrection::find_grid_file() {
  char** paths = OSRGetPROJSearchPaths();
  std::string found;
  for (char** p = paths; p && *p && found.empty(); ++p)
    for (const char* name : {"egm96_15.gtx", "us_nga_egm96_15.tif"}) {
      const std::filesystem::path f = std::filesystem::path(*p) / name;
      std::error_code ec;
      if (std::filesystem::is_regular_file(f, ec)) {
        found = f.string();
        break;
      }
    }
  CSLDestroy(paths);
  return found;
}

GeoidCorrection::GeoidCorrection(const std::array<double, 6>& g, const std::string& crs_wkt, int width, int height,
                                 int step)
    : step_(std::max(step, 1)),
      nx_((width - 1 + step_ - 1) / step_ + 1),
      ny_((height - 1 + step_ - 1) / step_ + 1) {
  gdal::register_once();
  gdal::QuietErrors quiet;
  grid_file_ = find_grid_file();
  if (grid_file_.empty())
    throw std::runtime_error("the EGM96 geoid grid (egm96_15.gtx, Debian package proj-data) is not on PROJ's search path");
  gdal::Dataset grid(GDALOpen(grid_file_.c_str(), GA_ReadOnly));
  if (!grid) throw std::runtime_error(grid_file_ + ": cannot read the geoid grid: " + gdal::last_error());
  GDALDatasetH gh = gdal::handle(grid);
  const int gw = GDALGetRasterXSize(gh), ghh = GDALGetRasterYSize(gh);
  double ggt[6];
  if (GDALGetGeoTransform(gh, ggt) != CE_None || ggt[2] != 0.0 || ggt[4] != 0.0)
    throw std::runtime_error(grid_file_ + ": the geoid grid is not a north-up lon/lat grid");
  std::vector<float> n_grid(std::size_t(gw) * ghh);
  if (GDALRasterIO(GDALGetRasterBand(gh, 1), GF_Read, 0, 0, gw, ghh, n_grid.data(), gw, ghh, GDT_Float32, 0, 0) != CE_None)
    throw std::runtime_error(grid_file_ + ": read failed: " + gdal::last_error());

  OGRSpatialReferenceH src = OSRNewSpatialReference(crs_wkt.c_str());
  OGRSpatialReferenceH wgs = OSRNewSpatialReference(nullptr);
  OSRImportFromEPSG(wgs, 4326);
  OSRSetAxisMappingStrategy(src, OAMS_TRADITIONAL_GIS_ORDER);
  OSRSetAxisMappingStrategy(wgs, OAMS_TRADITIONAL_GIS_ORDER);  // x = lon, y = lat
  OGRCoordinateTransformationH to_wgs = OCTNewCoordinateTransformation(src, wgs);
  OSRDestroySpatialReference(src);
  OSRDestroySpatialReference(wgs);
  if (!to_wgs) throw std::runtime_error("the DEM's CRS cannot be transformed to WGS 84 for the geoid: " + gdal::last_error());

  nodes_.resize(std::size_t(nx_) * ny_);
  std::vector<double> xs(nodes_.size()), ys(nodes_.size());
  for (int l = 0; l < ny_; ++l)
    for (int k = 0; k < nx_; ++k) {
      const double i = node_sample(k, step_, width), j = node_sample(l, step_, height);
      xs[std::size_t(l) * nx_ + k] = g[0] + i * g[1] + j * g[2];
      ys[std::size_t(l) * nx_ + k] = g[3] + i * g[4] + j * g[5];
    }
  const int ok = OCTTransform(to_wgs, int(xs.size()), xs.data(), ys.data(), nullptr);
  OCTDestroyCoordinateTransformation(to_wgs);
  if (!ok) throw std::runtime_error("the DEM's samples cannot be placed in WGS 84 for the geoid");
  // Bilinear in the grid (pixel-is-area: node (c, r) at the centre of pixel
  // (c, r)); longitude wraps around the globe.
  auto at = [&](int c, int r) {
    c = ((c % gw) + gw) % gw;
    r = std::clamp(r, 0, ghh - 1);
    return double(n_grid[std::size_t(r) * gw + c]);
  };
  for (std::size_t n = 0; n < nodes_.size(); ++n) {
    const double fc = (xs[n] - ggt[0]) / ggt[1] - 0.5, fr = (ys[n] - ggt[3]) / ggt[5] - 0.5;
    const int c = int(std::floor(fc)), r = int(std::floor(fr));
    const double tc = fc - c, tr = fr - r;
    nodes_[n] = (1 - tr) * ((1 - tc) * at(c, r) + tc * at(c + 1, r)) + tr * ((1 - tc) * at(c, r + 1) + tc * at(c + 1, r + 1));
  }
  width_ = width;
  height_ = height;
}

double GeoidCorrection::undulation(double i, double j) const {
  int k = 0, l = 0;
  double tx = 0.0, ty = 0.0;
  locate(i, step_, width_, nx_, k, tx);
  locate(j, step_, height_, ny_, l, ty);
  auto node = [&](int a, int b) { return nodes_[std::size_t(b) * nx_ + a]; };
  return (1 - ty) * ((1 - tx) * node(k, l) + tx * node(k + 1, l)) + ty * ((1 - tx) * node(k, l + 1) + tx * node(k + 1, l + 1));
}

void GeoidCorrection::to_orthometric(int x0, int y0, int w, int h, float* heights, const std::uint8_t* state) const {
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      const std::size_t k = std::size_t(r) * w + c;
      if (!state || state[k]) heights[k] = float(double(heights[k]) - undulation(x0 + c, y0 + r));
    }
}

}  // namespace ig::terrain
