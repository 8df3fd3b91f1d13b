#pragma once
// Chooses the Level1 grid size each frame from the previous frame's ratio
// R = Level1 pixels / all terrain pixels (the paper's rule):
//   R < a1 -> one step up the ladder, R > a2 -> one step down, else keep.
// The first frame uses the largest size the scene allows.
//
// One size step changes Level1's area about fourfold, so R can jump from
// below a1 to above a2: with the bare rule a steady view can flip between
// two sizes forever. So a step down is taken only when the smaller size is
// predicted to keep R >= a1, with R_smaller ~ k * R; k is learnt from the
// steps actually taken (starting at 0.35); R > 0.98 (Level1 covers all the
// terrain) always steps down. When no size fits, the larger one (more
// detail, the seam further away) is kept.

#include <vector>

namespace ig::lod {

struct SizeControllerOptions {
  double a1 = 0.50;
  double a2 = 0.80;
  double initial_shrink_factor = 0.35;  // first guess of R(smaller) / R(larger)
};

class Level1SizeController {
 public:
  // ladder: vertices a side, increasing (e.g. 33, 65, ..., 1025), already
  // capped to what the scene allows; must not be empty.
  Level1SizeController(std::vector<int> ladder, SizeControllerOptions options = {});

  // Size for this frame given last frame's ratio (negative or NaN = no
  // measurement: keep the size).
  int update(double last_ratio);
  // The same with a prediction of this frame's R for every ladder size
  // (lod/level1_coverage_predictor.h): the smallest size whose predicted R,
  // corrected by what the last measurement said of the last prediction (the
  // share of Level0 pixels the frame really shows), reaches a1 is taken at once (growing at once, shrinking only with a 0.05 margin:
  // hysteresis). Settles on a new view in one or two frames instead of one
  // ladder step per frame. An empty prediction falls back to update(ratio).
  int update(double last_ratio, const std::vector<double>& predicted);
  double correction() const { return correction_; }
  int size() const { return ladder_[index_]; }
  const std::vector<int>& ladder() const { return ladder_; }
  double shrink_factor() const { return k_; }
  void set_thresholds(double a1, double a2);

 private:
  std::vector<int> ladder_;
  SizeControllerOptions options_;
  int index_;
  double k_;                   // learnt R(smaller) / R(larger)
  int last_step_ = 0;          // +1 grew, -1 shrank, 0 kept (previous decision)
  double ratio_before_ = -1.0;  // R measured before the last step
  double correction_ = 1.0;     // h: the share of predicted Level0 pixels the frames show, smoothed
  double last_prediction_ = -1.0;  // predicted R of the size chosen last frame
};

// The ladder 33, 65, ..., 1025 limited to sizes that fit in the DEM
// (at most its smaller side) and to max_size. At least {33} (or the DEM
// size when it is smaller than 33: a 2x2 DEM gets {2}).
std::vector<int> level1_ladder(int dem_width, int dem_height, int max_size = 1025);

}  // namespace ig::lod
