// ig info's description of a loaded DEM (dem_info_json, terrain/dem_loader.h).
#include "terrain/dem_loader.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <numeric>
#include <vector>

#include "water/water_map.h"

namespace ig::terrain {

namespace {

// A number as ig info writes it: integral values as integers,
// a float by its own shortest decimal (not its double's 17 digits), and
// null when not finite.
template <typename T>
nlohmann::ordered_json json_number(T v) {
  if (!std::isfinite(double(v))) return nullptr;
  if (double(v) == std::trunc(double(v)) && std::fabs(double(v)) < 9.0e15) return std::int64_t(v);
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  return std::strtod(std::string(buf, res.ptr).c_str(), nullptr);
}

// The water terrain.water found or read (dem_info_json's "water").
nlohmann::ordered_json water_json(const Heightfield& hf, const water::WaterMap& map) {
  nlohmann::ordered_json w;
  w["source"] = map.source();
  w["bodies"] = map.bodies().size();
  std::int64_t samples = 0;
  double area = 0.0;
  for (const auto& b : map.bodies()) {
    samples += b.samples;
    area += b.area_m2;
  }
  w["samples"] = samples;
  w["area_km2"] = json_number(std::round(area / 1e3) / 1e3);
  std::vector<std::size_t> order(map.bodies().size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return map.bodies()[a].samples > map.bodies()[b].samples; });
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (std::size_t k : order) {
    const water::WaterBody& b = map.bodies()[k];
    nlohmann::ordered_json o;
    o["kind"] = water::water_kind_name(b.kind);
    o["level_m"] = json_number(b.level_m);
    o["samples"] = b.samples;
    o["area_km2"] = json_number(std::round(b.area_m2 / 1e3) / 1e3);
    o["samples_box"] = {b.min_i, b.min_j, b.max_i, b.max_j};
    if (hf.georef) {
      const auto& g = hf.georef->grid_to_crs;
      const double i = 0.5 * (b.min_i + b.max_i), j = 0.5 * (b.min_j + b.max_j);
      o["centre"] = {json_number(g[0] + i * g[1] + j * g[2]), json_number(g[3] + i * g[4] + j * g[5])};
    }
    list.push_back(std::move(o));
  }
  w["list"] = std::move(list);
  return w;
}

}  // namespace

std::string dem_info_json(const Heightfield& hf, const water::WaterMap* water, bool water_off) {
  nlohmann::ordered_json o;
  o["width"] = hf.width;
  o["height"] = hf.height;
  o["spacing_x_m"] = json_number(hf.spacing_x_m);
  o["spacing_y_m"] = json_number(hf.spacing_y_m);
  o["min_m"] = json_number(hf.min_m);
  o["max_m"] = json_number(hf.max_m);
  o["mean_m"] = json_number(hf.mean_m);
  o["nodata_count"] = hf.nodata_count;
  if (hf.void_fill) {  // GDAL loads: how the voids were (or would be) filled
    o["void_fill"] = {{"algorithm", "GDALFillNodata"},
                      {"max_distance", hf.void_fill->max_distance},
                      {"smoothing_iterations", hf.void_fill->smoothing_iterations},
                      {"deep_count", hf.deep_void_count},
                      {"deep_fill", "layers"}};
  }
  o["crs"] = nullptr;
  if (hf.georef && !hf.georef->crs_name.empty()) o["crs"] = hf.georef->crs_name;
  o["geographic"] = hf.georef && hf.georef->geographic;
  o["source"] = hf.source;
  if (hf.source_tiles > 0) {
    o["tiles"] = hf.source_tiles;
    o["reprojected_tiles"] = hf.reprojected_tiles;
  }
  if (hf.georef) {
    const auto& g = hf.georef->grid_to_crs;
    auto at = [&g](double i, double j) {
      return nlohmann::ordered_json::array(
          {json_number(g[0] + i * g[1] + j * g[2]), json_number(g[3] + i * g[4] + j * g[5])});
    };
    const double ie = hf.width - 1, je = hf.height - 1;
    // Corner sample centres, [x, y] in the DEM's CRS (lon, lat for geographic).
    o["corners"] = {{"sw", at(0, 0)}, {"se", at(ie, 0)}, {"nw", at(0, je)}, {"ne", at(ie, je)}};
    const auto [west, south, east, north] = *hf.crs_bounds();
    o["bounds"] = {{"west", json_number(west)}, {"south", json_number(south)}, {"east", json_number(east)},
                   {"north", json_number(north)}};
  }
  if (water) {
    o["water"] = water_json(hf, *water);
  } else if (water_off) {
    o["water"] = nullptr;
  }
  // One line; invalid UTF-8 in a path or CRS name replaced, not thrown.
  return o.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

}  // namespace ig::terrain
