#include "water/water_file.h"

#include <gdal.h>
#include <gdal_alg.h>
#include <ogr_api.h>
#include <ogr_srs_api.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

#include "terrain/gdal_support.h"
#include "water/water_levels.h"

namespace ig::water {
namespace {

namespace fs = std::filesystem;
namespace gdal = terrain::gdal;
using gdal::number_arg;

struct SrsDeleter {
  void operator()(void* s) const { OSRDestroySpatialReference(static_cast<OGRSpatialReferenceH>(s)); }
};
using Srs = std::unique_ptr<void, SrsDeleter>;
struct TransformDeleter {
  void operator()(void* t) const { OCTDestroyCoordinateTransformation(static_cast<OGRCoordinateTransformationH>(t)); }
};
using Transform = std::unique_ptr<void, TransformDeleter>;
struct GeometryDeleter {
  void operator()(void* g) const { OGR_G_DestroyGeometry(static_cast<OGRGeometryH>(g)); }
};
using Geometry = std::unique_ptr<void, GeometryDeleter>;

// The DEM's grid as a GDAL geotransform (north-up rows, pixel corners).
std::array<double, 6> dem_geotransform(const terrain::Heightfield& hf) {
  const auto& g = hf.georef->grid_to_crs;
  std::array<double, 6> gt{0, g[1], -g[2], 0, g[4], -g[5]};
  gt[0] = g[0] - 0.5 * gt[1] - (hf.height - 0.5) * gt[2];
  gt[3] = g[3] - 0.5 * gt[4] - (hf.height - 0.5) * gt[5];
  return gt;
}

std::string dem_bounds_text(const terrain::Heightfield& hf) {
  const auto b = *hf.crs_bounds();
  return "DEM " + number_arg(b[0]) + ".." + number_arg(b[2]) + " x " + number_arg(b[1]) + ".." + number_arg(b[3]) +
         " in its CRS";
}

// A grid of body labels (north-up rows as GDAL reads them; 0 = land) into a
// map (south-up), bodies numbered by their first sample, all Mapped;
// label_of_body (if given) gets each body's label.
WaterMap map_from_labels(const std::vector<std::int32_t>& labels, int w, int h, const std::string& path,
                         std::vector<std::int32_t>* label_of_body = nullptr) {
  WaterMap map(w, h);
  map.set_source(path);
  std::vector<std::int32_t> body_of_label;
  std::vector<WaterRun> runs;
  for (int j = 0; j < h; ++j) {
    const std::int32_t* row = labels.data() + std::size_t(h - 1 - j) * w;
    runs.clear();
    for (int i = 0; i < w;) {
      const std::int32_t l = row[i];
      int e = i + 1;
      while (e < w && row[e] == l) ++e;
      if (l > 0) {
        if (std::size_t(l) >= body_of_label.size()) body_of_label.resize(std::size_t(l) + 1, -1);
        if (body_of_label[l] < 0) {
          body_of_label[l] = std::int32_t(map.bodies().size());
          if (label_of_body) label_of_body->push_back(l);
          WaterBody b;
          b.kind = WaterKind::Mapped;
          map.bodies().push_back(b);
        }
        runs.push_back({i, e, std::uint32_t(body_of_label[l])});
      }
      i = e;
    }
    map.add_row(j, runs);
  }
  return map;
}

gdal::Dataset dem_grid_dataset(const terrain::Heightfield& hf, GDALDataType type, const std::string& path) {
  GDALDriverH mem = GDALGetDriverByName("MEM");
  gdal::Dataset ds(mem ? GDALCreate(mem, "", hf.width, hf.height, 1, type, nullptr) : nullptr);
  if (!ds) throw WaterFileError(path, "no memory for a " + std::to_string(hf.width) + "x" + std::to_string(hf.height) +
                                          " water grid: " + gdal::last_error("GDAL's MEM driver failed"));
  auto gt = dem_geotransform(hf);
  GDALSetGeoTransform(gdal::handle(ds), gt.data());
  GDALSetProjection(gdal::handle(ds), hf.georef->crs_wkt.c_str());
  return ds;
}

std::vector<std::int32_t> read_labels(GDALDatasetH ds, int w, int h, const std::string& path) {
  std::vector<std::int32_t> labels(std::size_t(w) * h);
  if (GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Read, 0, 0, w, h, labels.data(), w, h, GDT_Int32, 0, 0) != CE_None)
    throw WaterFileError(path, "reading the rasterized water failed: " + gdal::last_error("unknown GDAL error"));
  return labels;
}

Srs dem_srs(const terrain::Heightfield& hf) {
  Srs srs(OSRNewSpatialReference(nullptr));
  OSRSetAxisMappingStrategy(static_cast<OGRSpatialReferenceH>(srs.get()), OAMS_TRADITIONAL_GIS_ORDER);
  if (OSRSetFromUserInput(static_cast<OGRSpatialReferenceH>(srs.get()), hf.georef->crs_wkt.c_str()) != OGRERR_NONE)
    return nullptr;
  return srs;
}

// Polygons: one label per feature, burned as gdal_rasterize burns them.
WaterMap read_polygons(const terrain::Heightfield& hf, GDALDatasetH ds, const std::string& path,
                       const std::optional<std::string>& level_attribute) {
  OGRLayerH layer = GDALDatasetGetLayer(ds, 0);
  if (!layer) throw WaterFileError(path, "its first layer cannot be read: " + gdal::last_error("unknown GDAL error"));
  const std::string name = OGR_L_GetName(layer);
  OGRSpatialReferenceH layer_srs = OGR_L_GetSpatialRef(layer);
  if (!layer_srs)
    throw WaterFileError(path, "layer '" + name + "' has no coordinate reference system (give it one, e.g. "
                                                  "ogr2ogr -a_srs EPSG:4326)");
  if (OGR_L_GetFeatureCount(layer, TRUE) == 0) throw WaterFileError(path, "layer '" + name + "' is empty (no features)");
  int attribute = -1;
  if (level_attribute) {
    OGRFeatureDefnH defn = OGR_L_GetLayerDefn(layer);
    attribute = OGR_FD_GetFieldIndex(defn, level_attribute->c_str());
    if (attribute < 0) throw WaterFileError(path, "layer '" + name + "' has no attribute '" + *level_attribute + "'");
    const OGRFieldType type = OGR_Fld_GetType(OGR_FD_GetFieldDefn(defn, attribute));
    if (type != OFTInteger && type != OFTInteger64 && type != OFTReal)
      throw WaterFileError(path, "attribute '" + *level_attribute + "' is not numeric (" +
                                     OGR_GetFieldTypeName(type) + "); a level is a number of metres");
  }
  Srs source(OSRClone(layer_srs));
  OSRSetAxisMappingStrategy(static_cast<OGRSpatialReferenceH>(source.get()), OAMS_TRADITIONAL_GIS_ORDER);
  Srs target = dem_srs(hf);
  Transform to_dem(target ? OCTNewCoordinateTransformation(static_cast<OGRSpatialReferenceH>(source.get()),
                                                           static_cast<OGRSpatialReferenceH>(target.get()))
                          : nullptr);
  if (!to_dem)
    throw WaterFileError(path, "layer '" + name + "' cannot be transformed to the DEM's CRS: " +
                                   gdal::last_error("no transformation"));

  std::vector<Geometry> owned;
  std::vector<OGRGeometryH> geometries;
  std::vector<double> burn;
  std::vector<float> levels;
  std::int64_t features = 0;
  OGR_L_ResetReading(layer);
  while (OGRFeatureH f = OGR_L_GetNextFeature(layer)) {
    ++features;
    std::unique_ptr<void, void (*)(void*)> feature(f, [](void* p) { OGR_F_Destroy(static_cast<OGRFeatureH>(p)); });
    OGRGeometryH g = OGR_F_GetGeometryRef(f);
    if (!g || OGR_G_IsEmpty(g) || OGR_G_GetDimension(g) != 2) continue;  // points and lines hold no water
    Geometry copy(OGR_G_GetLinearGeometry(g, 0.0, nullptr));  // curves as line strings
    if (!copy || OGR_G_Transform(static_cast<OGRGeometryH>(copy.get()), static_cast<OGRCoordinateTransformationH>(to_dem.get())) != OGRERR_NONE)
      throw WaterFileError(path, "feature " + std::to_string(OGR_F_GetFID(f)) + " of layer '" + name +
                                     "' cannot be transformed to the DEM's CRS");
    if (attribute >= 0) {
      if (!OGR_F_IsFieldSetAndNotNull(f, attribute))
        throw WaterFileError(path, "feature " + std::to_string(OGR_F_GetFID(f)) + " has no value for '" + *level_attribute + "'");
      const double v = OGR_F_GetFieldAsDouble(f, attribute);
      if (!std::isfinite(v) || std::fabs(v) > 1e5)
        throw WaterFileError(path, "feature " + std::to_string(OGR_F_GetFID(f)) + ": '" + *level_attribute + "' is " +
                                       number_arg(v) + ", not a level in metres");
      levels.push_back(float(v));
    }
    geometries.push_back(static_cast<OGRGeometryH>(copy.get()));
    owned.push_back(std::move(copy));
    burn.push_back(double(geometries.size()));
  }
  if (geometries.empty())
    throw WaterFileError(path, "layer '" + name + "' has no polygons (" + std::to_string(features) +
                                   " features, all points, lines or empty)");

  gdal::Dataset grid = dem_grid_dataset(hf, GDT_Int32, path);
  int band = 1;
  CPLErrorReset();
  if (GDALRasterizeGeometries(gdal::handle(grid), 1, &band, int(geometries.size()), geometries.data(), nullptr,
                              nullptr, burn.data(), nullptr, nullptr, nullptr) != CE_None)
    throw WaterFileError(path, "rasterizing its polygons failed: " + gdal::last_error("unknown GDAL error"));
  const std::vector<std::int32_t> labels = read_labels(gdal::handle(grid), hf.width, hf.height, path);
  std::vector<std::int32_t> label_of_body;
  WaterMap map = map_from_labels(labels, hf.width, hf.height, path, &label_of_body);
  if (map.empty()) {
    OGREnvelope e{};
    OGR_L_GetExtent(layer, &e, TRUE);
    throw WaterFileError(path, "its polygons do not cover a DEM sample (layer '" + name + "' spans " +
                                   number_arg(e.MinX) + ".." + number_arg(e.MaxX) + " x " + number_arg(e.MinY) + ".." +
                                   number_arg(e.MaxY) + " in its CRS; " + dem_bounds_text(hf) + ")");
  }
  map.summarise_bodies(hf.spacing_x_m * hf.spacing_y_m);
  if (attribute >= 0) {  // a body's label is its feature's burn value: index + 1
    for (std::size_t b = 0; b < label_of_body.size(); ++b) map.bodies()[b].level_m = levels[label_of_body[b] - 1];
  } else {
    choose_levels(map, hf);
  }
  return map;
}

// 4-connected regions of water samples (north-up mask) as labels 1, 2, ...
std::vector<std::int32_t> label_regions(const std::vector<std::uint8_t>& water, int w, int h) {
  std::vector<std::int32_t> labels(water.size(), 0);
  std::vector<std::size_t> stack;
  std::int32_t next = 0;
  for (std::size_t start = 0; start < water.size(); ++start) {
    if (!water[start] || labels[start]) continue;
    labels[start] = ++next;
    stack.push_back(start);
    while (!stack.empty()) {
      const std::size_t p = stack.back();
      stack.pop_back();
      const int i = int(p % std::size_t(w)), j = int(p / std::size_t(w));
      auto visit = [&](std::size_t q) {
        if (water[q] && !labels[q]) {
          labels[q] = next;
          stack.push_back(q);
        }
      };
      if (i > 0) visit(p - 1);
      if (i + 1 < w) visit(p + 1);
      if (j > 0) visit(p - std::size_t(w));
      if (j + 1 < h) visit(p + std::size_t(w));
    }
  }
  return labels;
}

// A raster mask: warped onto the DEM's grid by gdalwarp, nearest neighbour.
WaterMap read_mask(const terrain::Heightfield& hf, GDALDatasetH ds, const std::string& path) {
  double gt[6];
  if (!GDALGetSpatialRef(ds) || GDALGetGeoTransform(ds, gt) != CE_None)
    throw WaterFileError(path, "has no coordinate reference system or georeferencing (give it one, e.g. "
                               "gdal_translate -a_srs EPSG:4326 -a_ullr ...)");
  const auto b = *hf.crs_bounds();
  // Where the mask lies in the DEM's CRS, to tell "no overlap" from "no water".
  void* transform = GDALCreateGenImgProjTransformer(ds, nullptr, nullptr, hf.georef->crs_wkt.c_str(), FALSE, 0, 1);
  if (!transform)
    throw WaterFileError(path, "its CRS cannot be transformed to the DEM's: " + gdal::last_error("no transformation"));
  double suggested[6];
  int sw = 0, sh = 0;
  const CPLErr err = GDALSuggestedWarpOutput(ds, GDALGenImgProjTransform, transform, suggested, &sw, &sh);
  GDALDestroyGenImgProjTransformer(transform);
  if (err != CE_None) throw WaterFileError(path, "cannot be placed on the DEM: " + gdal::last_error("warp failed"));
  const double x0 = suggested[0], x1 = suggested[0] + sw * suggested[1];
  const double y0 = suggested[3] + sh * suggested[5], y1 = suggested[3];
  if (x1 <= b[0] || x0 >= b[2] || y1 <= b[1] || y0 >= b[3])
    throw WaterFileError(path, "does not overlap the DEM (it spans " + number_arg(x0) + ".." + number_arg(x1) + " x " +
                                   number_arg(y0) + ".." + number_arg(y1) + "; " + dem_bounds_text(hf) + ")");
  const std::vector<std::string> args = {
      "-of",  "MEM",         "-t_srs", hf.georef->crs_wkt, "-te", number_arg(b[0]), number_arg(b[1]),
      number_arg(b[2]), number_arg(b[3]), "-ts", std::to_string(hf.width), std::to_string(hf.height),
      "-r",   "near",        "-ot",    "Float32",          "-wo", "INIT_DEST=0"};
  gdal::Dataset warped = gdal::warp(ds, "", args);
  if (!warped) throw WaterFileError(path, "cannot be warped onto the DEM: " + gdal::last_error("unknown GDAL error"));
  std::vector<float> v(std::size_t(hf.width) * hf.height);
  if (GDALRasterIO(GDALGetRasterBand(gdal::handle(warped), 1), GF_Read, 0, 0, hf.width, hf.height, v.data(), hf.width,
                   hf.height, GDT_Float32, 0, 0) != CE_None)
    throw WaterFileError(path, "reading the warped mask failed: " + gdal::last_error("unknown GDAL error"));
  int has_nodata = 0;
  const double nodata = GDALGetRasterNoDataValue(GDALGetRasterBand(gdal::handle(warped), 1), &has_nodata);
  std::vector<std::uint8_t> water(v.size());
  for (std::size_t k = 0; k < v.size(); ++k)
    water[k] = v[k] != 0.0f && std::isfinite(v[k]) && !(has_nodata && double(v[k]) == nodata);
  warped.reset();
  v = {};
  WaterMap map = map_from_labels(label_regions(water, hf.width, hf.height), hf.width, hf.height, path);
  map.summarise_bodies(hf.spacing_x_m * hf.spacing_y_m);
  choose_levels(map, hf);
  return map;
}

}  // namespace

WaterFileError::WaterFileError(const std::string& path, const std::string& reason)
    : std::runtime_error(gdal::one_line(path + ": " + reason)) {}

WaterMap read_water_file(const terrain::Heightfield& hf, const std::string& path,
                         const std::optional<std::string>& level_attribute) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (path.empty() || st.type() == fs::file_type::not_found) throw WaterFileError(path, "no such file");
  if (!hf.georef || hf.georef->crs_wkt.empty())
    throw WaterFileError(path, "the DEM (" + hf.source + ") has no georeferencing to place water data on");
  gdal::register_once();
  gdal::QuietErrors quiet;
  gdal::Dataset ds(GDALOpenEx(path.c_str(), GDAL_OF_RASTER | GDAL_OF_VECTOR | GDAL_OF_READONLY | GDAL_OF_VERBOSE_ERROR,
                              nullptr, nullptr, nullptr));
  if (!ds) {
    const std::string msg = gdal::last_error();
    throw WaterFileError(path, "GDAL cannot open it as a raster or a vector layer" + (msg.empty() ? "" : ": " + msg));
  }
  if (GDALDatasetGetLayerCount(gdal::handle(ds)) > 0) return read_polygons(hf, gdal::handle(ds), path, level_attribute);
  if (GDALGetRasterCount(gdal::handle(ds)) > 0) {
    if (level_attribute)
      throw WaterFileError(path, "a raster has no attributes: level_attribute '" + *level_attribute +
                                     "' needs a vector layer of polygons");
    return read_mask(hf, gdal::handle(ds), path);
  }
  throw WaterFileError(path, "has neither raster bands nor vector layers");
}

}  // namespace ig::water
