#pragma once
// Image-space error of a rendered frame against the reference frame of the
// same camera (design.md, "Error against run time"; definitions in
// docs/bench.md): horizon/silhouette offset per column, relative depth error,
// colour PSNR and holes. Works on read-back buffers only; no GL calls except
// in read_frame_image().

#include <cstddef>
#include <cstdint>
#include <vector>

#include "gl/render_target.h"
#include "render/camera.h"

namespace ig::stats {

// One frame as read back from a gl::RenderTarget: top row first, RGBA8 colour
// and reversed-Z float depth, where 0 (the clear value, infinitely far) means
// no terrain was drawn there: sky.
struct FrameImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4
  std::vector<float> depth;        // width * height
  // Terrain pixel: depth > 0. A NaN depth counts as sky (and is counted).
  bool terrain(int x, int y) const { return depth[std::size_t(y) * width + x] > 0.0f; }
};

FrameImage read_frame_image(const gl::RenderTarget& target);

struct ImageErrorOptions {
  // A reference-terrain pixel within this many rows (and columns) of a
  // reference sky pixel lies on a silhouette: sky there in the method image
  // is horizon error, not an interior hole.
  int silhouette_rows = 2;
  int silhouette_cols = 1;
  bool list_interior_holes = false;  // fill ImageError::interior_hole_pixels
};

struct ImageError {
  // Horizon: per column, the topmost terrain row in each image. Columns with
  // terrain in neither image are left out. A column with terrain in only one
  // image counts as if the other image's horizon lay just below the bottom
  // row (row = height): the offset is the whole terrain run that is missing.
  int horizon_columns = 0;            // columns with terrain in either image
  int horizon_one_sided_columns = 0;  // of which terrain in only one image
  double horizon_mean_px = 0.0;       // mean |offset| over horizon_columns (0 when none)
  double horizon_max_px = 0.0;

  // Depth: |D_method - D_ref| / D_ref over pixels that are terrain in both,
  // D = view distance along the axis (Camera::depth_to_view_distance).
  long long depth_pixels = 0;
  double depth_rel_p95 = 0.0;  // nearest-rank 95th percentile (0 when no pixels)
  double depth_rel_max = 0.0;

  // Colour: RGB of every pixel (alpha carries method data and is ignored).
  double mse = 0.0;      // mean squared difference per channel, 8-bit levels
  double psnr_db = 0.0;  // psnr_db_from_mse(mse, width * height * 3)

  // Coverage.
  long long reference_terrain_pixels = 0;
  long long holes = 0;                 // reference terrain, sky in the method image
  long long interior_pixels = 0;       // reference terrain away from silhouettes
  long long interior_holes = 0;        // holes among interior_pixels
  // Holes below the method image's own topmost terrain row in their column:
  // sky seen through the surface (cracks, gaps between patches, missing
  // tiles) rather than a silhouette drawn too low, which only uncovers sky
  // above that row.
  long long enclosed_holes = 0;
  long long extra_terrain_pixels = 0;  // method terrain where the reference has sky
  long long invalid_depth_pixels = 0;  // non-finite depth in the method image
  std::vector<std::size_t> interior_hole_pixels;  // y * width + x, when asked for
};

// Compares `method` with `reference`, both rendered with `camera`. Throws
// std::invalid_argument when the sizes differ or a buffer has the wrong length.
ImageError image_error(const FrameImage& method, const FrameImage& reference, const render::Camera& camera,
                       const ImageErrorOptions& options = {});

// PSNR in dB of 8-bit data from a mean squared error over `samples` channel
// values. Identical images (mse 0) get a finite value: that of a single one-level
// difference among the samples, 10*log10(255^2 * samples), above any
// non-identical pair, so tables and CSV files never hold infinity.
double psnr_db_from_mse(double mse, double samples);

}  // namespace ig::stats
