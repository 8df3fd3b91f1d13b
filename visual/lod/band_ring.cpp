#include "lod/band_ring.h"

#include <algorithm>
#include <cmath>

namespace ig::lod {

bool BandRing::may_reach(glm::ivec2 piece_lo, glm::ivec2 piece_hi, double z_lo, double z_hi) const {
  if (hi.x < lo.x || hi.y < lo.y) return false;
  // An upper bound of a fragment's distance from the eye as drawn: the
  // farthest horizontal offset plus the farthest vertical one, the
  // curvature's drop (d^2 / 2R) counted twice over for margin.
  const glm::dvec2 a = glm::dvec2(piece_lo) * spacing - glm::dvec2(eye);
  const glm::dvec2 b = glm::dvec2(piece_hi) * spacing - glm::dvec2(eye);
  const double fx = std::max(std::abs(a.x), std::abs(b.x)), fy = std::max(std::abs(a.y), std::abs(b.y));
  const double horizontal = std::sqrt(fx * fx + fy * fy);
  const double drop = earth_radius_m > 0.0 ? horizontal * horizontal / earth_radius_m : 0.0;
  const double vertical = std::max(std::abs(z_hi - eye.z), std::abs(z_lo - drop - eye.z));
  const double window_m = tolerance_m + kWindowPerMetre * (horizontal + vertical);
  // The search's points lie within the window of the fragment, itself over
  // the piece; one sample more for the shader's float arithmetic.
  const glm::dvec2 reach = window_m / spacing + 1.0;
  return piece_lo.x - reach.x <= hi.x && piece_hi.x + reach.x >= lo.x && piece_lo.y - reach.y <= hi.y &&
         piece_hi.y + reach.y >= lo.y;
}

}  // namespace ig::lod
