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

std::vector<int> level1_ladder(int dem_width, int dem_height, int max_size) {
  const int limit = std::min({dem_width, dem_height, max_size});
  std::vector<int> ladder;
  for (int n = 33; n <= 1025 && n <= limit; n = (n - 1) * 2 + 1) ladder.push_back(n);
  if (ladder.empty()) ladder.push_back(std::max(2, std::min(limit, 33)));
  return ladder;
}

}  // namespace ig::lod
