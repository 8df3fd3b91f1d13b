#pragma once
// The two-level method's settings (docs/twolevel.md), one struct for every
// place that sets them: the scenario file (render.twolevel, io/scenario.cpp),
// the command line (ig bench --skip-pass), Modbus (a1, a2, alpha,
// level0_budget) and the method itself (visual/render/twolevel_method.h).
// Plain data, no GL: io and visual both include it. Defaults: the paper's
// settings, except where docs/twolevel.md says why not.

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace ig::options {

struct TwoLevelOptions {
  // Valid ranges, checked against these by every place that sets a value
  // (scenario file, command line, Modbus registers). a1 and a2 lie in
  // (0, 1) with a1 < a2 (check_thresholds).
  static constexpr int kMinLevel0Budget = 2, kMaxLevel0Budget = 10'000'000;
  static constexpr double kMaxAlpha = 1e9;  // alpha in (0, kMaxAlpha]
  // The budget "auto" takes at the reference display (lod/level0_budget.h),
  // and what a method given 0 directly uses.
  static constexpr int kReferenceLevel0Budget = 524288;

  // Level0 ROAM triangles (the paper: 2048). 0 = "auto": from the finest
  // channel's pixels per radian (lod/level0_budget.h), resolved by the
  // session when it sets up its channels; a method given 0 directly uses
  // the reference display's budget.
  int level0_budget = 0;
  // Level1 also covers the ground under a low eye (lod/level1_selection.h).
  bool eye_guard = true;
  double a1 = 0.50, a2 = 0.80;    // Level1 grows when R < a1, shrinks when R > a2
  double alpha = 2000.0;          // band factor: w_trans = (r0 / r1) * alpha * w1
  bool gaussian_beta = false;     // beta template: linear (default) or Gaussian
  int max_level1 = 1025;          // top of the Level1 ladder (33, 65, ..., 1025 vertices a side)
  int band_stride = 2;            // band geometry every k samples (it only carries uv)
  // The band's uv1 and beta found in Level0's fragment shader by marching
  // the pixel's ray against the height texture, only near the ring (true,
  // "inline"), or by the paper's separate band pass into its own target
  // (false, "target").
  bool band_inline = true;
  // Level0 lifted to a conservative upper envelope (lod/level0_envelope.h):
  // no ridge cut below the skyline, so no sky through Level0 terrain.
  bool level0_envelope = false;
  // Level0 refined on whole-triangle error ("whole",
  // lod::Level0Options::whole_triangle_error) instead of the nested midpoint
  // error ("midpoint", the paper's).
  bool level0_whole_error = false;
  // Size control predicts R for every ladder size from a grid of view rays
  // and jumps to the right size (lod/level1_coverage_predictor.h); false:
  // the paper's one step per frame on the measured R alone.
  bool predict_size = true;
  // Level0 clusters hidden behind nearer terrain are not drawn
  // (lod/horizon_culling.h); the picture is the same either way.
  bool horizon_culling = true;
  // For cost breakdowns only (ig bench --skip-pass): passes not drawn,
  // any of "level1", "band", "level0", "count". The image is then wrong.
  std::vector<std::string> skip_passes;

  // nullopt when 0 < a1 < a2 < 1, else why not: "a1 must ..." or "a2 must ...".
  static std::optional<std::string> check_thresholds(double a1, double a2) {
    auto num = [](double v) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%g", v);
      return std::string(buf);
    };
    if (!(a1 > 0.0 && a1 < 1.0)) return "a1 must be in (0, 1), got " + num(a1);
    if (!(a2 > 0.0 && a2 < 1.0)) return "a2 must be in (0, 1), got " + num(a2);
    if (!(a1 < a2)) return "a2 must be greater than a1 (a1 " + num(a1) + ", a2 " + num(a2) + ")";
    return std::nullopt;
  }
};

}  // namespace ig::options
