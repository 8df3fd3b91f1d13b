#pragma once
// Where the terrain has water: the DEM samples that are water, grouped into
// bodies, each with the one level its surface lies at. No GL.
//
// Samples are stored as runs per row ([begin, end) of one body), so the map
// costs memory in proportion to its shorelines, not to the DEM: the Sierra's
// 4097^2 samples take a few hundred kilobytes, and a paged DEM of any size
// keeps its water resident beside its pyramid. Rows are the Heightfield's
// (row 0 = south).
//
// Where the water ends between samples is the shore field's business
// (water/shore_field.h): the smooth shoreline the picture and the host
// queries share.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace ig::water {

// Where a body came from: found in the DEM (the sea, a lake) or read from
// the user's water file (terrain.water as a path).
enum class WaterKind : std::uint8_t { Sea, Lake, Mapped };
const char* water_kind_name(WaterKind kind);

struct WaterBody {
  WaterKind kind = WaterKind::Lake;
  float level_m = 0.0f;        // the surface's height (the DEM's vertical datum)
  std::int64_t samples = 0;    // DEM samples in the body
  double area_m2 = 0.0;        // samples * one sample's cell
  int min_i = 0, min_j = 0;    // bounding box of its samples, inclusive
  int max_i = -1, max_j = -1;
  bool touches_edge = false;   // a sample on the DEM's outer row or column
};

// Samples [begin, end) of one row belonging to body `body`.
struct WaterRun {
  int begin = 0;
  int end = 0;
  std::uint32_t body = 0;
};

class WaterMap {
 public:
  WaterMap() = default;
  // An empty map of width x height samples; rows are added in order with
  // add_row.
  WaterMap(int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }
  bool empty() const { return bodies_.empty(); }
  // What the water came from: "auto" (found in the DEM) or the water file's path.
  const std::string& source() const { return source_; }
  void set_source(std::string source) { source_ = std::move(source); }

  const std::vector<WaterBody>& bodies() const { return bodies_; }
  std::vector<WaterBody>& bodies() { return bodies_; }
  std::int64_t water_samples() const;

  // Appends row j's runs (j must be the next row; runs sorted, disjoint,
  // bodies already in bodies()). Throws std::logic_error otherwise.
  void add_row(int j, std::span<const WaterRun> runs);
  std::span<const WaterRun> row(int j) const;
  int rows_added() const { return int(row_start_.size()) - 1; }

  // The body sample (i, j) belongs to; nullopt for land and outside the grid.
  std::optional<std::uint32_t> body_at(int i, int j) const;
  bool is_water(int i, int j) const { return body_at(i, j).has_value(); }
  // Row j as bytes, 1 = water, 0 = land (out must hold width() bytes).
  void fill_row_mask(int j, std::uint8_t* out) const;

  // Fills bodies' samples, areas, bounding boxes and edge contact from the
  // runs (cell_area_m2: one sample's cell).
  void summarise_bodies(double cell_area_m2);

  bool operator==(const WaterMap& o) const;

 private:
  int width_ = 0, height_ = 0;
  std::string source_;
  std::vector<WaterBody> bodies_;
  std::vector<WaterRun> runs_;
  std::vector<std::size_t> row_start_{0};  // runs of row j: [row_start_[j], row_start_[j + 1])
};

}  // namespace ig::water
