#pragma once
// Temporal error (popping) of a method between two consecutive frames, set
// against the reference's change between the same two cameras: where the
// reference image changes because the view moved, the method's image should
// change by as much and no more. A mesh that changes abruptly (LOD switches
// without morphing) changes pixels the reference leaves alone. Definitions:
// docs/bench.md. Works on read-back buffers only; no GL.

#include <vector>

#include "stats/image_error.h"

namespace ig::stats {

// One image's luma, row-major like FrameImage, 8-bit levels (0..255).
struct LumaImage {
  int width = 0, height = 0;
  std::vector<float> luma;  // width * height
};

// Rec. 709 luma (environment::luma) of each pixel's stored RGB; alpha is
// ignored, as image_error() ignores it.
LumaImage luminance(const FrameImage& f);

struct TemporalError {
  // Mean over pixels of |(M_now - M_before) - (R_now - R_before)| in luma
  // levels: 0 when the method changes exactly as the reference does.
  double mean = 0.0;
  double method_change = 0.0;     // mean |M_now - M_before|
  double reference_change = 0.0;  // mean |R_now - R_before|
};

// M: the method's frames, R: the reference's at the same two cameras.
// Throws std::invalid_argument when an image is empty or malformed or the
// sizes differ.
TemporalError temporal_error(const LumaImage& method_before, const LumaImage& method_now,
                             const LumaImage& reference_before, const LumaImage& reference_now);

}  // namespace ig::stats
