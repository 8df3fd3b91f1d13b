#pragma once
// Full-resolution imagery around a point, for imagery finer than one GL
// texture: the scene draws an overview of the image everywhere
// and this size x size RGB8 wrap-around window (render/window_texture.h) of
// the full image where it covers a fragment. It follows the same point as
// the height window (Level1's centre, in DEM samples); a move uploads only
// the imagery rows and columns that scrolled in, copied out of the imagery's
// tile cache (terrain/imagery_loader.h, paged from GDAL).
//
// A move never makes a frame wait: every call asks the cache's background
// thread for the window's target rectangle and a tile of margin around it;
// when a move needs a tile that is not resident yet, the window keeps its
// previous placement (the overview is drawn where it does not cover) and
// moves on a later call, once the tiles are in. Such held moves and the
// tiles they missed are counted (stats()). Only centre_on_sample(c, true)
// waits: the first fill at load.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "render/window_texture.h"
#include "terrain/imagery_loader.h"

namespace ig::render {

class ImageryWindowTexture {
 public:
  struct Stats {
    long long moves = 0;          // moves made (uploads)
    long long held_moves = 0;     // calls that kept the old placement: a tile was not resident
    long long missing_tiles = 0;  // the non-resident tiles those calls found
  };

  // Reads imagery.paged (full_width() x full_height(), over the footprint of
  // a dem_w x dem_h DEM; shared, so it outlives the imagery). Throws
  // std::invalid_argument without paged imagery, gl::GlError if size does
  // not fit GL.
  ImageryWindowTexture(const terrain::Imagery& imagery, int dem_w, int dem_h, int size, const std::string& what);

  // Centres the window on the imagery under DEM sample `centre`; returns the
  // pixels uploaded (0 when it did not move or the move is held). wait:
  // read missing tiles now instead of holding (the first fill, at load).
  long long centre_on_sample(glm::ivec2 centre, bool wait = false);

  GLuint id() const { return tex_.id(); }
  bool placed() const { return tex_.placed(); }
  glm::ivec2 origin() const { return tex_.origin(); }  // in full-resolution pixels
  glm::ivec2 size() const { return tex_.size(); }
  glm::ivec2 full_size() const { return {full_w_, full_h_}; }
  long long uploaded_pixels() const { return tex_.uploaded_texels(); }
  const Stats& stats() const { return stats_; }
  const terrain::RgbTileCache& cache() const { return *pages_->cache; }
  // Tiles whose read failed (drawn grey; terrain::PagedImagery).
  std::int64_t failed_tiles() const { return *pages_->failed_tiles; }

 private:
  std::shared_ptr<const terrain::PagedImagery> pages_;
  int full_w_, full_h_, dem_w_, dem_h_;
  WindowTexture tex_;
  Stats stats_;
  std::vector<std::vector<terrain::Rgb8>> staged_;  // a move's rectangles, copied out of the cache
};

}  // namespace ig::render
