#pragma once
// GeoMipMapping's CPU side (de Boer 2000): the DEM cut into square blocks of
// kGeoMipBlockQuads x kGeoMipBlockQuads quads (33 x 33 vertices), each with a
// mip chain of regular grids at strides 1, 2, ..., 32 samples and, per
// level, its precomputed geometric error delta (the largest vertical
// distance between a full-resolution sample and that level's mesh).
//
// Cracks: a block whose neighbour is coarser draws that side at the
// neighbour's stride. The side's row of quads is replaced by a strip joining
// the coarse edge to the block's first inner row (a "zipper" of fans), so both
// blocks share exactly the same edge vertices and segments: no T-junctions.
// Where two adjacent sides are stitched their strips meet on the corner
// quad's diagonal. Unstitched blocks are the plain grid (split along the
// (i,j)-(i+1,j+1) diagonal like every grid in the IG). A stitched block's
// error is bounded piece by piece: its plain quads by the level's error,
// each strip by the strip's own exact error (computed on first use, cached).
//
// DEMs of any size: the block grid covers ceil((W-1)/32) x ceil((H-1)/32)
// blocks; vertices past the DEM's edge clamp onto it (the errors are those of
// the clamped meshes).

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <glm/vec2.hpp>

#include "lod/chunk_grid_error.h"
#include "terrain/heightfield.h"

namespace ig::lod {

constexpr int kGeoMipBlockQuads = 32;
constexpr int kGeoMipLevels = 6;  // level l: stride 2^l, 32 >> l quads a side

// Sides of a block, counter-clockwise from the south.
enum GeoMipSide { kSouth = 0, kEast = 1, kNorth = 2, kWest = 3 };

// What one block draws: its level and, per side, the level its edge is
// drawn at (>= level: the coarser of the block and that neighbour).
struct GeoMipConfig {
  int level = 0;
  std::array<int, 4> side_level{0, 0, 0, 0};
  bool stitched() const;
  std::uint32_t key() const;  // unique per configuration, < 2^15
};

// The triangles of a configuration: three corners each, vertex offsets
// (0..32) inside the block, counter-clockwise seen from above.
std::vector<glm::ivec2> geomipmap_triangles(const GeoMipConfig& config);
// Only the strip of a stitched side (empty when the side is not stitched):
// the row of quads along it, less the corner halves given to a stitched
// adjacent side. The rest of the block is plain level quads.
std::vector<glm::ivec2> geomipmap_strip_triangles(const GeoMipConfig& config, int side);

struct GeoMipBlock {
  int i0 = 0, j0 = 0;  // origin sample
  HeightRange heights;
  std::array<float, kGeoMipLevels> error{};   // metres, unstitched level mesh
  std::array<int, kGeoMipLevels> triangles{};  // non-degenerate, unstitched
};

class GeoMipMapBlocks {
 public:
  explicit GeoMipMapBlocks(const terrain::Heightfield& hf);

  int blocks_x() const { return blocks_x_; }
  int blocks_y() const { return blocks_y_; }
  const std::vector<GeoMipBlock>& blocks() const { return blocks_; }
  const GeoMipBlock& block(int bx, int by) const { return blocks_[size_t(by) * blocks_x_ + bx]; }
  double build_ms() const { return build_ms_; }

  // The error (metres) and drawn-triangle count of block (bx, by) in a
  // configuration: the precomputed level figures when unstitched; when
  // stitched, the error is the largest of the level's error (which bounds the
  // plain quads, a subset of the level's grid) and each stitched strip's
  // exact error (strip_error), and the count is that of its triangles.
  struct Stats {
    float error_m = 0.0f;
    int triangles = 0;
  };
  Stats stats(int bx, int by, const GeoMipConfig& config) const;
  // The error (metres) of one stitched side's strip (0 when the side is not
  // stitched), computed on first use and cached. With the level's error it
  // bounds the block piece by piece, each piece seen from its own distance.
  float strip_error(int bx, int by, const GeoMipConfig& config, int side) const;

  // The configuration of block (bx, by) given every block's level
  // (levels[by * blocks_x + bx]): each side at the coarser of the two
  // levels; the DEM's outer sides at the block's own level.
  GeoMipConfig config_of(int bx, int by, const std::vector<int>& levels) const;

 private:
  const terrain::Heightfield& hf_;
  int blocks_x_ = 0, blocks_y_ = 0;
  std::vector<GeoMipBlock> blocks_;
  double build_ms_ = 0.0;
  mutable std::unordered_map<std::uint64_t, int> stitched_triangles_;  // edge blocks only
  mutable std::unordered_map<std::uint64_t, float> strip_errors_;
  mutable std::unordered_map<std::uint32_t, std::vector<glm::ivec2>> triangles_cache_;
};

// The coarsest level whose projected error delta / D * pixels_per_radian is
// at most tau_px (D clamped to min_distance_m so D = 0 stays finite).
int geomipmap_select_level(const std::array<float, kGeoMipLevels>& error, double distance_m,
                           double min_distance_m, double pixels_per_radian, double tau_px);

}  // namespace ig::lod
