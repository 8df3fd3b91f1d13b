#include "lod/level1_size_controller.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ig::lod {

Level1SizeController::Level1SizeController(std::vector<int> ladder, SizeControllerOptions options)
    : ladder_(std::move(ladder)), options_(options), k_(options.initial_shrink_factor) {
  if (ladder_.empty()) throw std::invalid_argument("Level1 size ladder is empty");
  index_ = int(ladder_.size()) - 1;  // first frame: the largest size
}

void Level1SizeController::set_thresholds(double a1, double a2) {
  options_.a1 = a1;
  options_.a2 = a2;
}

int Level1SizeController::update(double ratio) {
  if (!(ratio >= 0.0)) return size();  // no measurement (also NaN): keep
  // Learn k from the step just taken: R(smaller) / R(larger).
  if (last_step_ != 0 && ratio_before_ > 0.0 && ratio > 0.0) {
    const double observed = last_step_ < 0 ? ratio / ratio_before_ : ratio_before_ / ratio;
    k_ = std::clamp(0.5 * k_ + 0.5 * observed, 0.02, 0.98);
  }
  int step = 0;
  if (ratio < options_.a1 && index_ + 1 < int(ladder_.size())) step = +1;
  // R near 1 says nothing about the smaller size (Level1 covers everything): shrink.
  if (ratio > options_.a2 && index_ > 0 && (ratio > 0.98 || ratio * k_ >= options_.a1)) step = -1;
  index_ += step;
  last_step_ = step;
  ratio_before_ = ratio;
  return size();
}

int Level1SizeController::update(double ratio, const std::vector<double>& predicted) {
  if (predicted.size() != ladder_.size()) return update(ratio);
  // The prediction counts every terrain ray; the frame shows fewer Level0
  // pixels than that (the coarse Level0 cuts distant ridges: sky where the
  // rays hit), so the measured R runs higher. Model: Level0 shows a fraction
  // h of its predicted pixels, R = r / (r + h (1 - r)); h from the last
  // frame's pair (measured, predicted), smoothed; near R = 1 it says nothing.
  if (ratio > 0.0 && ratio < 0.98 && last_prediction_ > 0.0 && last_prediction_ < 0.98) {
    const double h = (1.0 / ratio - 1.0) / (1.0 / last_prediction_ - 1.0);
    correction_ = std::clamp(0.25 * correction_ + 0.75 * h, 0.05, 4.0);
  }
  auto corrected = [&](int i) {
    const double r = predicted[size_t(i)];
    return r <= 0.0 ? 0.0 : r / (r + correction_ * (1.0 - r));
  };
  int target = int(ladder_.size()) - 1;
  for (int i = 0; i < int(ladder_.size()); ++i)
    if (corrected(i) >= options_.a1) {
      target = i;
      break;
    }
  const int before = index_;
  // Grow to the predicted size unless the measurement says this size is
  // already enough (measured beats predicted for the size in use).
  if (target > index_ && !(ratio >= options_.a1)) index_ = target;
  // Shrink when the smaller size is predicted to keep R >= a1: at once when
  // the measured R says this size is too big (> a2), else only with a 0.05
  // margin (no flip-flop on a prediction at the threshold).
  else if (target < index_ && corrected(target) >= options_.a1 + (ratio > options_.a2 ? 0.0 : 0.05)) index_ = target;
  // The measured R says this size covers (nearly) everything but the
  // prediction cannot tell what a smaller one would: the paper's step down.
  else if (index_ == before && ratio > options_.a2 && index_ > 0 && (ratio > 0.98 || ratio * k_ >= options_.a1))
    --index_;
  last_step_ = index_ > before ? 1 : index_ < before ? -1 : 0;
  ratio_before_ = ratio;
  last_prediction_ = predicted[size_t(index_)];
  return size();
}

std::vector<int> level1_ladder(int dem_width, int dem_height, int max_size) {
  const int limit = std::min({dem_width, dem_height, max_size});
  std::vector<int> ladder;
  for (int n = 33; n <= 1025 && n <= limit; n = (n - 1) * 2 + 1) ladder.push_back(n);
  if (ladder.empty()) ladder.push_back(std::max(2, std::min(limit, 33)));
  return ladder;
}

}  // namespace ig::lod
