#include "stats/temporal_error.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

#include "environment/sky_light.h"

namespace ig::stats {
namespace {

void check(const LumaImage& a, const LumaImage& first, const char* which) {
  if (a.width <= 0 || a.height <= 0 || a.luma.size() != std::size_t(a.width) * std::size_t(a.height))
    throw std::invalid_argument(std::string("temporal_error: ") + which + " image is malformed (" +
                                std::to_string(a.width) + "x" + std::to_string(a.height) + ", " +
                                std::to_string(a.luma.size()) + " values)");
  if (a.width != first.width || a.height != first.height)
    throw std::invalid_argument(std::string("temporal_error: ") + which + " image is " + std::to_string(a.width) +
                                "x" + std::to_string(a.height) + ", the method's before image " +
                                std::to_string(first.width) + "x" + std::to_string(first.height));
}

}  // namespace

LumaImage luminance(const FrameImage& f) {
  const std::size_t n = std::size_t(std::max(f.width, 0)) * std::size_t(std::max(f.height, 0));
  if (f.rgba.size() != 4 * n)
    throw std::invalid_argument("luminance: " + std::to_string(f.width) + "x" + std::to_string(f.height) +
                                " image with " + std::to_string(f.rgba.size()) + " colour values");
  LumaImage out;
  out.width = f.width;
  out.height = f.height;
  out.luma.resize(n);
  for (std::size_t p = 0; p < n; ++p)
    out.luma[p] = environment::luma({float(f.rgba[4 * p]), float(f.rgba[4 * p + 1]), float(f.rgba[4 * p + 2])});
  return out;
}

TemporalError temporal_error(const LumaImage& mb, const LumaImage& mn, const LumaImage& rb, const LumaImage& rn) {
  check(mb, mb, "method before");
  check(mn, mb, "method now");
  check(rb, mb, "reference before");
  check(rn, mb, "reference now");
  double sum = 0.0, method = 0.0, reference = 0.0;
  for (std::size_t p = 0; p < mb.luma.size(); ++p) {
    const double dm = double(mn.luma[p]) - double(mb.luma[p]);
    const double dr = double(rn.luma[p]) - double(rb.luma[p]);
    sum += std::abs(dm - dr);
    method += std::abs(dm);
    reference += std::abs(dr);
  }
  const double n = double(mb.luma.size());
  return {sum / n, method / n, reference / n};
}

}  // namespace ig::stats
