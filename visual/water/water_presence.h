#pragma once
// Where water shows, coarsely, for deferred shading's water pass to find its
// pixels with one cheap texture read each (shaders/water.frag, water_near).
// No GL.
//
// Level 0 has one texel per kPresenceBlock x kPresenceBlock texels of the
// share grid (water/shore_field.h): their mean share. Each next level
// halves the side and averages. A byte rounds a mean under half a level to
// 0: water that would change a pixel by less than that. A pixel whose
// footprint spans at most a level's block lies within the 2 x 2 texels of
// that level around its centre, so one bilinear read there is above 0 when
// water may show in it; the level is a sixteenth of the share texture.

#include <cstdint>
#include <vector>

#include "water/shore_field.h"
#include "water/water_map.h"

namespace ig::water {

inline constexpr int kPresenceBlock = 4;

struct PresenceLevel {
  int width = 0, height = 0;
  std::vector<std::uint8_t> texels;  // row-major, row 0 = south; mean share * 255
};

// The levels from the share grid's rows (water/shore_field.h), given in
// order; level 0's sides are powers of two (past the grid: no water), so
// each level is half the one before, down to 1 x 1, as a texture's mips.
class PresenceBuilder {
 public:
  explicit PresenceBuilder(const ShoreGrid& grid);
  void add_row(int j, const std::uint8_t* share);
  std::vector<PresenceLevel> levels() const;

 private:
  ShoreGrid grid_;
  int width_ = 1, height_ = 1;
  std::vector<double> mean_;  // level 0's mean shares
};

// The same over every step-th sample of a map's share grid.
std::vector<PresenceLevel> water_presence(const WaterMap& map, int step);

}  // namespace ig::water
