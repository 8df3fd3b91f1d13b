// DEM loading for every supported input (GDAL rasters, 16-bit images, .hgt,
// folders and VRTs through terrain/dem_mosaic.h): one read path, then the
// shared nodata fill, flip and statistics. Each format's checks name the
// file and the reason next to the read; images are read in
// terrain/dem_image_loader.cpp.
#include "terrain/dem_loader.h"
#include "terrain/dem_image_loader.h"
#include "terrain/dem_mosaic.h"
#include "terrain/gdal_support.h"
#include "terrain/gdal_tile_reader.h"
#include "terrain/huge_pages.h"
#include "terrain/paged_dem_loader.h"
#include "terrain/paged_heights.h"
#include "terrain/void_fill.h"

#include <gdal.h>
#include <cpl_conv.h>
#include <cpl_error.h>
#include <ogr_srs_api.h>

#include <GeographicLib/Ellipsoid.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <new>
#include <numbers>
#include <string_view>
#include <vector>

namespace ig::terrain {

namespace {

namespace fs = std::filesystem;

constexpr std::uintmax_t kHgt1201Bytes = 2ull * 1201 * 1201;  // 2 884 802
constexpr std::uintmax_t kHgt3601Bytes = 2ull * 3601 * 3601;  // 25 934 402
constexpr float kSrtmVoid = -32768.0f;

using gdal::one_line;

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

void flip_rows(std::vector<float>& h, int w, int ht) {
  for (int j = 0; j < ht / 2; ++j) {
    auto a = h.begin() + std::ptrdiff_t(j) * w;
    auto b = h.begin() + std::ptrdiff_t(ht - 1 - j) * w;
    std::swap_ranges(a, a + w, b);
  }
}

// ----------------------------------------------------------------- GDAL ---

// GDAL messages often start with the file name ("x.tif: ...", "x.tif, band
// 1: ..."); ours already do, so drop that prefix.
std::string without_path(std::string msg, const std::string& path) {
  auto trim_front = [&msg] {
    std::size_t k = 0;
    while (k < msg.size() && std::strchr(" ,:'`\"", msg[k])) ++k;
    msg.erase(0, k);
  };
  trim_front();
  for (const std::string& p : {path, fs::path(path).filename().string()}) {
    if (!p.empty() && msg.compare(0, p.size(), p) == 0) {
      msg.erase(0, p.size());
      trim_front();
      break;
    }
  }
  return msg;
}

// Metres per vertical unit of the band ("m", "ft", ...); 1 when unknown.
double vertical_unit_to_metres(const char* unit) {
  if (!unit) return 1.0;
  const std::string u = lower(unit);
  if (u == "ft" || u == "foot" || u == "feet" || u == "international foot") return 0.3048;
  if (u == "ftus" || u == "us survey foot" || u == "us-ft" || u == "foot_us")
    return 1200.0 / 3937.0;
  return 1.0;
}

std::string crs_short_name(OGRSpatialReferenceH srs) {
  const char* auth = OSRGetAuthorityName(srs, nullptr);
  const char* code = OSRGetAuthorityCode(srs, nullptr);
  if (auth && code && *auth && *code) return std::string(auth) + ":" + code;
  if (OGRSpatialReferenceH clone = OSRClone(srs)) {
    std::string name;
    if (OSRAutoIdentifyEPSG(clone) == OGRERR_NONE) {
      auth = OSRGetAuthorityName(clone, nullptr);
      code = OSRGetAuthorityCode(clone, nullptr);
      if (auth && code && *auth && *code) name = std::string(auth) + ":" + code;
    }
    OSRDestroySpatialReference(clone);
    if (!name.empty()) return name;
  }
  const char* n = OSRGetName(srs);
  return n ? std::string(n) : std::string();
}

// The heights read whole (they fit the memory budget): one RasterIO, flip,
// decode, void fill over the whole grid.
void read_whole_heights(Heightfield& hf, GDALRasterBandH band, const std::string& path, int w, int ht,
                        const SampleDecoding& dec, const VoidFillOptions& void_fill) {
  hf.width = w;
  hf.height = ht;
  hf.source = path;
  const std::size_t n = std::size_t(w) * std::size_t(ht);
  try {
    reserve_in_huge_pages(hf.heights, n);  // scattered queries: terrain/huge_pages.h
    hf.heights.resize(n);
  } catch (const std::bad_alloc&) {
    throw DemError(path, "out of memory for a " + size_text(w, ht) + " grid");
  }

  CPLErrorReset();
  const CPLErr err = GDALRasterIO(band, GF_Read, 0, 0, w, ht, hf.heights.data(), w, ht,
                                  GDT_Float32, 0, 0);
  if (err != CE_None) {
    const std::string msg = without_path(gdal::last_error(), path);
    throw DemError(path, "read failed (truncated or corrupt file?)" +
                             (msg.empty() ? std::string() : ": " + msg));
  }
  flip_rows(hf.heights, w, ht);

  const auto is_valid = [&](float v) { return dec.valid(v); };
  std::size_t valid = 0;
  for (std::size_t k = 0; k < n; ++k) valid += is_valid(hf.heights[k]);
  if (valid == 0)
    throw DemError(path, "all " + std::to_string(n) + " samples are nodata");
  // The void mask (a byte per sample, 420 MB for 20481^2) only when there
  // are voids, so a void-free DEM's load peaks at its heights.
  std::vector<std::uint8_t> state;
  if (valid < n) {
    state.resize(n);
    for (std::size_t k = 0; k < n; ++k) state[k] = is_valid(hf.heights[k]);
  }

  // Band scale/offset and vertical units (feet) to metres, valid samples only.
  if (dec.scale != 1.0 || dec.offset != 0.0 || dec.unit_m != 1.0) {
    for (std::size_t k = 0; k < n; ++k)
      if (state.empty() || state[k]) hf.heights[k] = float((hf.heights[k] * dec.scale + dec.offset) * dec.unit_m);
  }
  if (dec.geoid) dec.geoid->to_orthometric(0, 0, w, ht, hf.heights.data(), state.empty() ? nullptr : state.data());
  hf.void_fill = void_fill;
  if (state.empty()) return;
  try {
    const VoidFillResult filled = fill_voids(hf.heights, state, w, ht, void_fill);
    hf.nodata_count = filled.voids;
    hf.deep_void_count = filled.deep;
  } catch (const std::bad_alloc&) {
    throw DemError(path, "out of memory filling the voids of a " + size_text(w, ht) + " grid");
  } catch (const std::exception& e) {
    throw DemError(path, e.what());
  }
}

Heightfield load_with_gdal(const std::string& path, const DemLoadOptions& opts,
                           bool is_hgt) {
  gdal::register_once();
  gdal::QuietErrors quiet;

  gdal::Dataset ds(GDALOpenEx(
      path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY | GDAL_OF_VERBOSE_ERROR, nullptr,
      nullptr, nullptr));
  if (!ds) {
    const std::string msg = without_path(gdal::last_error(), path);
    if (is_hgt)
      throw DemError(path, "not a recognised raster format (SRTM .hgt files must be named "
                           "after their tile, e.g. N44W072.hgt)");
    if (msg.empty() || msg.find("not recognized as a supported file format") != std::string::npos)
      throw DemError(path, "not a recognised raster format");
    // A driver claimed the file but could not open it (e.g. a TIFF cut short).
    throw DemError(path, "cannot open (truncated or corrupt file?): " + msg);
  }
  GDALDatasetH h = ds.get();

  const int bands = GDALGetRasterCount(h);
  if (bands != 1)
    throw DemError(path, "has " + std::to_string(bands) +
                             " raster bands; a DEM must have exactly one");
  const std::int64_t w64 = GDALGetRasterXSize(h), h64 = GDALGetRasterYSize(h);
  // Paged when the float heights exceed the memory budget.
  const std::size_t budget = std::size_t(std::max(opts.memory_budget_mb, 1)) << 20;
  const bool paged = w64 > 0 && h64 > 0 && std::uint64_t(w64) * std::uint64_t(h64) * sizeof(float) > budget;
  check_size(path, w64, h64, paged);
  const int w = int(w64), ht = int(h64);
  GDALRasterBandH band = GDALGetRasterBand(h, 1);
  if (GDALDataTypeIsComplex(GDALGetRasterDataType(band)))
    throw DemError(path, "complex-valued raster is not a DEM");

  // How samples decode: voids (band nodata, non-finite, SRTM void), band
  // scale/offset and vertical units (feet) to metres.
  int has_nodata = 0;
  const double nodata = GDALGetRasterNoDataValue(band, &has_nodata);
  const bool nodata_is_nan = has_nodata && std::isnan(nodata);
  const bool nodata_fits = has_nodata && !nodata_is_nan && std::fabs(nodata) <= FLT_MAX;
  SampleDecoding dec;
  dec.nodata = nodata_fits ? float(nodata) : kSrtmVoid;
  int has_scale = 0, has_offset = 0;
  dec.scale = GDALGetRasterScale(band, &has_scale);
  dec.offset = GDALGetRasterOffset(band, &has_offset);
  if (!has_scale) dec.scale = 1.0;
  if (!has_offset) dec.offset = 0.0;
  dec.unit_m = vertical_unit_to_metres(GDALGetRasterUnitType(band));
  if (opts.vertical_datum == "ellipsoid") {  // heights above WGS 84: to above the geoid (EGM96)
    std::array<double, 6> gt{};
    OGRSpatialReferenceH srs = GDALGetSpatialRef(h);
    if (GDALGetGeoTransform(h, gt.data()) != CE_None || !srs)
      throw DemError(path, "vertical_datum \"ellipsoid\" needs a georeferenced DEM (the geoid depends on where it is)");
    char* wkt = nullptr;
    OSRExportToWkt(srs, &wkt);
    const std::string crs_wkt = wkt ? wkt : "";
    CPLFree(wkt);
    // Our (i, j) (south-up sample centres) to the CRS, as GeoReference::grid_to_crs below.
    const std::array<double, 6> g{gt[0] + 0.5 * gt[1] + (ht - 0.5) * gt[2], gt[1], -gt[2],
                                  gt[3] + 0.5 * gt[4] + (ht - 0.5) * gt[5], gt[4], -gt[5]};
    try {
      dec.geoid = std::make_shared<const GeoidCorrection>(g, crs_wkt, w, ht);
    } catch (const std::exception& e) {
      throw DemError(path, e.what());
    }
  } else if (opts.vertical_datum != "geoid") {
    throw DemError(path, "unknown vertical_datum '" + opts.vertical_datum + "' (expected geoid or ellipsoid)");
  }

  Heightfield hf;
  if (paged) {
    // GDAL's block cache (5 % of RAM by default) would sit beside the tile cache.
    if (GDALGetCacheMax64() > (GIntBig(256) << 20)) GDALSetCacheMax64(GIntBig(256) << 20);
    try {
      hf = load_paged_heights(path, dec, opts.void_fill, budget, opts.page_tile);
    } catch (const std::exception& e) {
      throw DemError(path, without_path(e.what(), path));
    }
  } else {
    read_whole_heights(hf, band, path, w, ht, dec, opts.void_fill);
  }

  // Georeferencing and spacing.
  std::array<double, 6> gt{};
  const bool has_gt = GDALGetGeoTransform(h, gt.data()) == CE_None;
  OGRSpatialReferenceH srs = GDALGetSpatialRef(h);
  if (has_gt) {
    GeoReference geo;
    if (srs) {
      char* wkt = nullptr;
      if (OSRExportToWkt(srs, &wkt) == OGRERR_NONE && wkt) geo.crs_wkt = wkt;
      CPLFree(wkt);
      geo.crs_name = crs_short_name(srs);
      geo.geographic = OSRIsGeographic(srs) != 0;
    }
    // GDAL's geotransform maps pixel CORNERS of north-up rows; ours maps
    // sample centres of south-up rows (j = height - 1 - row).
    geo.grid_to_crs = {gt[0] + 0.5 * gt[1] + (ht - 0.5) * gt[2], gt[1], -gt[2],
                       gt[3] + 0.5 * gt[4] + (ht - 0.5) * gt[5], gt[4], -gt[5]};

    double east_per_unit = 1.0, north_per_unit = 1.0;  // metres per CRS unit
    if (srs && geo.geographic) {
      const double centre_lat = gt[3] + 0.5 * w * gt[4] + 0.5 * ht * gt[5];
      if (!(std::fabs(centre_lat) <= 90.0))
        throw DemError(path, "geographic georeferencing puts the centre at latitude " +
                                 std::to_string(centre_lat) + ", outside -90..90");
      OGRErr e1 = OGRERR_NONE, e2 = OGRERR_NONE;
      double a = OSRGetSemiMajor(srs, &e1);
      double inv_f = OSRGetInvFlattening(srs, &e2);
      if (e1 != OGRERR_NONE || !(a > 0)) a = 6378137.0;
      if (e2 != OGRERR_NONE || !(inv_f >= 0)) inv_f = 298.257223563;
      double unit_rad = OSRGetAngularUnits(srs, nullptr);
      if (!(unit_rad > 0)) unit_rad = std::numbers::pi / 180.0;
      const MetresPerAngle mpa = metres_per_angle(centre_lat, a, inv_f, unit_rad);
      east_per_unit = mpa.east;
      north_per_unit = mpa.north;
    } else if (srs) {
      double lin = OSRGetLinearUnits(srs, nullptr);
      if (!(lin > 0)) lin = 1.0;
      east_per_unit = north_per_unit = lin;
    }
    hf.spacing_x_m = std::hypot(gt[1] * east_per_unit, gt[4] * north_per_unit);
    hf.spacing_y_m = std::hypot(gt[2] * east_per_unit, gt[5] * north_per_unit);
    if (!(hf.spacing_x_m > 0) || !(hf.spacing_y_m > 0) || !std::isfinite(hf.spacing_x_m) ||
        !std::isfinite(hf.spacing_y_m))
      throw DemError(path, "invalid pixel size in the georeferencing");
    hf.georef = std::move(geo);
  }
  if (opts.spacing_m) hf.spacing_x_m = hf.spacing_y_m = *opts.spacing_m;
  hf.finalize_stats();
  return hf;
}

}  // namespace

DemError::DemError(const std::string& path, const std::string& reason)
    : std::runtime_error(one_line(path + ": " + reason)), path_(path), reason_(reason) {}

MetresPerAngle metres_per_angle(double lat_deg, double a, double inv_f, double unit_rad) {
  const GeographicLib::Ellipsoid ellipsoid(a, inv_f > 0 ? 1.0 / inv_f : 0.0);
  return {ellipsoid.MeridionalCurvatureRadius(lat_deg) * unit_rad, ellipsoid.CircleRadius(lat_deg) * unit_rad};
}

Heightfield load_dem(const std::string& path, const DemLoadOptions& opts) {
  const std::string& enc = opts.encoding;
  if (enc != "auto" && enc != "terrain-rgb" && enc != "png16" && enc != "gdal")
    throw DemError(path, "unknown encoding '" + enc +
                             "' (expected auto, terrain-rgb, png16 or gdal)");
  if (!std::isfinite(opts.scale) || !std::isfinite(opts.offset))
    throw DemError(path, "scale and offset must be finite numbers");
  if (opts.spacing_m && !(*opts.spacing_m > 0 && std::isfinite(*opts.spacing_m)))
    throw DemError(path, "spacing must be a positive number of metres");
  const VoidFillOptions& fill = opts.void_fill;
  if (fill.max_distance < 1 || fill.max_distance > VoidFillOptions::kMaxVoidSearch)
    throw DemError(path, "void_fill max_distance must be 1.." + std::to_string(VoidFillOptions::kMaxVoidSearch) +
                             " samples (got " + std::to_string(fill.max_distance) + ")");
  if (fill.smoothing_iterations < 0 || fill.smoothing_iterations > VoidFillOptions::kMaxVoidSmoothing)
    throw DemError(path, "void_fill smoothing_iterations must be 0.." +
                             std::to_string(VoidFillOptions::kMaxVoidSmoothing) + " (got " +
                             std::to_string(fill.smoothing_iterations) + ")");

  // File-system checks first, so the common mistakes read plainly.
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (path.empty() || st.type() == fs::file_type::not_found)
    throw DemError(path, "no such file");
  if (ec) throw DemError(path, "cannot access: " + ec.message());
  if (st.type() == fs::file_type::directory) {
    if (enc != "auto" && enc != "gdal") throw DemError(path, "a folder of tiles is read through GDAL, not as " + enc);
    const auto mosaic_ptr = std::make_shared<const DemMosaic>(path);
    const DemMosaic& mosaic = *mosaic_ptr;
    Heightfield hf;
    try {
      hf = load_with_gdal(mosaic.vrt_path(), opts, false);
    } catch (const DemError& e) {
      throw DemError(path, "mosaic of " + std::to_string(mosaic.tile_count()) + " tiles: " + e.reason());
    }
    if (hf.paged) {  // tiles are read from the mosaic's in-memory VRTs after the load
      auto paged = std::make_shared<PagedHeights>(*hf.paged);
      paged->source_keep_alive = mosaic_ptr;
      hf.paged = std::move(paged);
    }
    hf.source = path;
    hf.source_tiles = mosaic.tile_count();
    hf.reprojected_tiles = mosaic.reprojected_count();
    return hf;
  }
  if (st.type() != fs::file_type::regular)
    throw DemError(path, "not a regular file");
  const std::uintmax_t bytes = fs::file_size(path, ec);
  if (ec) throw DemError(path, "cannot access: " + ec.message());
  if (bytes == 0) throw DemError(path, "empty file (0 bytes)");

  unsigned char magic[8] = {};
  {
    std::ifstream f(path, std::ios::binary);
    if (!f) throw DemError(path, std::string("cannot open for reading: ") + std::strerror(errno));
    f.read(reinterpret_cast<char*>(magic), sizeof magic);
  }
  static const unsigned char kPngMagic[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  const bool png_signature = bytes >= 8 && std::memcmp(magic, kPngMagic, 8) == 0;
  const std::string ext = lower(fs::path(path).extension().string());
  const bool is_hgt = ext == ".hgt";

  if (enc == "png16" || enc == "terrain-rgb") return load_with_oiio(path, opts, enc);
  if (enc == "auto" && (png_signature || ext == ".png"))
    return load_with_oiio(path, opts, "auto");

  if (is_hgt && bytes != kHgt1201Bytes && bytes != kHgt3601Bytes)
    throw DemError(path, "truncated or wrong-size SRTM .hgt: " + std::to_string(bytes) +
                             " bytes, expected 2884802 (1201x1201) or 25934402 (3601x3601)");
  return load_with_gdal(path, opts, is_hgt);
}

}  // namespace ig::terrain
