#pragma once
// Renders single frames of a scenario at a chosen size, sample count and
// detail setting, and the picture measures the picture tests use: a 4 x 4
// supersampled, box-filtered reference, the error along sky/terrain
// boundaries against it, and the high-pass luminance of the ground.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "io/scenario.h"
#include "render/test/headless_run.h"
#include "session/scenario_runner.h"

namespace picture {

struct Shot {
  int w = 0, h = 0;
  std::vector<std::uint8_t> rgba;  // top row first
  std::vector<float> depth;        // 0: sky (reversed-Z clear value)
  std::vector<float> sky_fraction;  // per pixel; only for box-filtered shots
};

struct ShotSpec {
  int w = 320, h = 240;
  std::string aa = "off";  // render.antialiasing
  bool detail = true;
  std::string method = "reference";
};

inline std::string dem_dir() {
  const char* d = std::getenv("IG_DEM_DIR");
  return d ? std::string(d) : std::string();
}

// Frame `frame` of `scenario` (its path and settings; size, samples, detail
// and method from `spec`).
inline Shot render(ig::io::Scenario scenario, int frame, const ShotSpec& spec) {
  scenario.render.antialiasing = spec.aa;  // msaa: the default 4 samples
  scenario.render.shading.ground_detail = spec.detail;
  ig::session::RunOptions o = headless_run(spec.w, spec.h);
  o.method = spec.method;
  ig::session::ScenarioRunner runner(std::move(scenario), o);
  runner.render_frame(frame);
  const auto& target = *runner.channels().front().target;
  return Shot{spec.w, spec.h, target.read_rgba(), target.read_depth(), {}};
}

// The mean of each f x f block (colour), and the share of its samples that are sky.
inline Shot box_filter(const Shot& big, int f) {
  Shot s{big.w / f, big.h / f, {}, {}, {}};
  s.rgba.assign(std::size_t(s.w) * s.h * 4, 0);
  s.depth.assign(std::size_t(s.w) * s.h, 0.0f);
  s.sky_fraction.assign(std::size_t(s.w) * s.h, 0.0f);
  for (int y = 0; y < s.h; ++y)
    for (int x = 0; x < s.w; ++x) {
      double c[4] = {0, 0, 0, 0};
      int sky = 0;
      for (int v = 0; v < f; ++v)
        for (int u = 0; u < f; ++u) {
          const std::size_t q = std::size_t(y * f + v) * big.w + (x * f + u);
          for (int k = 0; k < 4; ++k) c[k] += big.rgba[q * 4 + k];
          sky += big.depth[q] == 0.0f;
        }
      const std::size_t p = std::size_t(y) * s.w + x;
      for (int k = 0; k < 4; ++k) s.rgba[p * 4 + k] = std::uint8_t(std::lround(c[k] / (f * f)));
      s.sky_fraction[p] = float(sky) / float(f * f);
      s.depth[p] = sky == f * f ? 0.0f : 1.0f;
    }
  return s;
}

struct EdgeError {
  double mean = 0.0;  // mean |difference| (levels, mean of R, G, B) over boundary pixels
  long long pixels = 0;
};

// Against a box-filtered supersampled shot: pixels whose block holds both
// sky and terrain samples, away from the image border.
inline EdgeError boundary_error(const Shot& shot, const Shot& supersampled) {
  EdgeError e;
  double sum = 0.0;
  for (int y = 1; y + 1 < shot.h; ++y)
    for (int x = 1; x + 1 < shot.w; ++x) {
      const std::size_t p = std::size_t(y) * shot.w + x;
      const float f = supersampled.sky_fraction[p];
      if (f <= 0.0f || f >= 1.0f) continue;
      double d = 0.0;
      for (int k = 0; k < 3; ++k) d += std::abs(int(shot.rgba[p * 4 + k]) - int(supersampled.rgba[p * 4 + k]));
      sum += d / 3.0;
      ++e.pixels;
    }
  e.mean = e.pixels ? sum / double(e.pixels) : 0.0;
  return e;
}

inline double luminance(const Shot& s, int x, int y) {
  const std::size_t p = (std::size_t(y) * s.w + x) * 4;
  return 0.2126 * s.rgba[p] + 0.7152 * s.rgba[p + 1] + 0.0722 * s.rgba[p + 2];
}

// Standard deviation of (luminance - its 5 x 5 mean) over the image's lower
// quarter: the fine texture a low-flying pilot reads speed and height from.
inline double highpass_std_lower_quarter(const Shot& s) {
  double sum = 0.0, sq = 0.0;
  long long n = 0;
  for (int y = std::max(2, s.h * 3 / 4); y + 2 < s.h; ++y)
    for (int x = 2; x + 2 < s.w; ++x) {
      double mean = 0.0;
      for (int v = -2; v <= 2; ++v)
        for (int u = -2; u <= 2; ++u) mean += luminance(s, x + u, y + v);
      const double d = luminance(s, x, y) - mean / 25.0;
      sum += d;
      sq += d * d;
      ++n;
    }
  const double m = sum / double(n);
  return std::sqrt(std::max(0.0, sq / double(n) - m * m));
}

// Mean |difference| of two shots of the same size (levels, mean of R, G, B).
inline double mean_abs_difference(const Shot& a, const Shot& b) {
  double sum = 0.0;
  for (std::size_t p = 0; p < std::size_t(a.w) * a.h; ++p)
    for (int k = 0; k < 3; ++k) sum += std::abs(int(a.rgba[p * 4 + k]) - int(b.rgba[p * 4 + k]));
  return sum / (3.0 * double(a.w) * a.h);
}

}  // namespace picture
