#include "lod/level0_budget.h"

#include <algorithm>
#include <cmath>

namespace ig::lod {
namespace {
constexpr double kReferenceBudget = 524288.0;
constexpr double kReferencePixelsPerRadian = 887.0;  // 1024 rows, 60 degrees
constexpr double kMinBudget = 32768.0, kMaxBudget = 4194304.0;
}  // namespace

double pixels_per_radian(int rows, double fov_y_deg) {
  const double half = 0.5 * fov_y_deg * M_PI / 180.0;
  return rows / (2.0 * std::tan(half));
}

int level0_budget_for_display(double pixels_per_radian) {
  if (!std::isfinite(pixels_per_radian) || !(pixels_per_radian > 0.0)) return int(kReferenceBudget);
  const double b = kReferenceBudget * std::sqrt(pixels_per_radian / kReferencePixelsPerRadian);
  return int(std::clamp(std::round(b / 1024.0) * 1024.0, kMinBudget, kMaxBudget));
}

}  // namespace ig::lod
