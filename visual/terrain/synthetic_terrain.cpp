#include "terrain/synthetic_terrain.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "terrain/lattice_hash.h"

namespace ig::terrain {

namespace {

// 16 unit gradient directions, every 22.5 degrees (literal values, so no
// libm call can change them).
constexpr double kGrad[16][2] = {
    {1.0, 0.0},
    {0.92387953251128674, 0.38268343236508978},
    {0.70710678118654757, 0.70710678118654757},
    {0.38268343236508978, 0.92387953251128674},
    {0.0, 1.0},
    {-0.38268343236508978, 0.92387953251128674},
    {-0.70710678118654757, 0.70710678118654757},
    {-0.92387953251128674, 0.38268343236508978},
    {-1.0, 0.0},
    {-0.92387953251128674, -0.38268343236508978},
    {-0.70710678118654757, -0.70710678118654757},
    {-0.38268343236508978, -0.92387953251128674},
    {0.0, -1.0},
    {0.38268343236508978, -0.92387953251128674},
    {0.70710678118654757, -0.70710678118654757},
    {0.92387953251128674, -0.38268343236508978},
};

inline double fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

inline double corner(std::uint32_t ix, std::uint32_t iy, std::uint32_t s, double dx,
                     double dy) {
  const double* g = kGrad[hash3(ix, iy, s) & 15u];
  return g[0] * dx + g[1] * dy;
}

// 2D gradient noise, roughly in [-1, 1].
inline double gradient_noise(double x, double y, std::uint32_t s) {
  const double fx = std::floor(x), fy = std::floor(y);
  const auto ix = static_cast<std::uint32_t>(static_cast<std::int64_t>(fx));
  const auto iy = static_cast<std::uint32_t>(static_cast<std::int64_t>(fy));
  const double dx = x - fx, dy = y - fy;
  const double n00 = corner(ix, iy, s, dx, dy);
  const double n10 = corner(ix + 1, iy, s, dx - 1.0, dy);
  const double n01 = corner(ix, iy + 1, s, dx, dy - 1.0);
  const double n11 = corner(ix + 1, iy + 1, s, dx - 1.0, dy - 1.0);
  const double u = fade(dx), v = fade(dy);
  const double a = n00 + (n10 - n00) * u;
  const double b = n01 + (n11 - n01) * u;
  return 1.41421356237309515 * (a + (b - a) * v);
}

inline double smoothstep(double lo, double hi, double v) {
  const double t = std::clamp((v - lo) / (hi - lo), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// Uniform double in [0, 1) from a hash.
inline double unit(std::uint32_t h) { return double(h) * (1.0 / 4294967296.0); }

void validate(const options::SyntheticTerrainOptions& p) {
  auto bad = [](const std::string& what) {
    throw std::invalid_argument("synthetic terrain: " + what);
  };
  const int n = p.size - 1;
  if (p.size < 3 || p.size > 16385 || (n & (n - 1)) != 0)
    bad("size " + std::to_string(p.size) +
        " is invalid (must be 2^n + 1 between 3 and 16385, e.g. 513, 1025)");
  if (p.octaves < 1 || p.octaves > 24)
    bad("octaves " + std::to_string(p.octaves) + " is out of range 1..24");
  if (!(p.spacing_m > 0) || !std::isfinite(p.spacing_m))
    bad("spacing_m " + std::to_string(p.spacing_m) + " must be a positive number");
  if (!(p.relief_m >= 0) || !std::isfinite(p.relief_m))
    bad("relief_m " + std::to_string(p.relief_m) + " must be >= 0");
  if (!std::isfinite(p.base_m)) bad("base_m " + std::to_string(p.base_m) + " must be finite");
  if (!(p.ridge_weight >= 0 && p.ridge_weight <= 1))
    bad("ridge_weight " + std::to_string(p.ridge_weight) + " must be in [0, 1]");
}

}  // namespace

Heightfield generate_synthetic_terrain(const options::SyntheticTerrainOptions& p) {
  validate(p);
  const int size = p.size;
  const double inv_n = 1.0 / double(size - 1);

  // Per-octave seed and domain offset (breaks the lattice alignment at the
  // origin, where gradient noise is always 0).
  struct Octave {
    std::uint32_t seed;
    double ox, oy;
  };
  std::vector<Octave> oct(std::size_t(p.octaves));
  for (int o = 0; o < p.octaves; ++o) {
    const std::uint32_t s = hash3(p.seed, std::uint32_t(o), 0x5EEDu);
    oct[std::size_t(o)] = {s, 64.0 + 128.0 * unit(hash3(s, 1u, 2u)),
                           64.0 + 128.0 * unit(hash3(s, 3u, 4u))};
  }
  // Large-scale tilt: one of 8 compass directions picked by the seed.
  constexpr double kTilt[8][2] = {{1, 0},
                                  {0.70710678118654757, 0.70710678118654757},
                                  {0, 1},
                                  {-0.70710678118654757, 0.70710678118654757},
                                  {-1, 0},
                                  {-0.70710678118654757, -0.70710678118654757},
                                  {0, -1},
                                  {0.70710678118654757, -0.70710678118654757}};
  const double* tilt = kTilt[hash3(p.seed, 0x7117u, 0u) & 7u];
  // Shape constants (tuned by eye against hillshades of real DEMs).
  constexpr double kTiltAmount = 0.18;     // slope across the map, in unnormalised units
  constexpr double kBaseFrequency = 3.0;   // first-octave cycles per map side
  constexpr double kGain = 0.5;            // amplitude ratio between octaves
  constexpr double kWarpFrequency = 1.2;   // domain warp: cycles per map side
  constexpr double kWarpAmount = 0.2;      // domain warp: displacement, map sides
  constexpr double kMacroFrequency = 1.6;  // where the ranges are: cycles per map side
  constexpr double kMacroAmount = 0.3;     // weight of the smooth macro relief
  constexpr double kMaskLo = 0.2, kMaskHi = 0.55;  // macro values: plain .. full mountains
  constexpr double kPlainDetail = 0.1;     // share of mountain detail kept on the plains
  constexpr double kShapeLin = 0.4;        // t' = kShapeLin t + (1 - kShapeLin) t^2
  const std::uint32_t macro_seed = hash3(p.seed, 0x3AC0u, 9u);
  const double macro_ox = 16.0 + 64.0 * unit(hash3(macro_seed, 1u, 6u));
  const double macro_oy = 16.0 + 64.0 * unit(hash3(macro_seed, 2u, 8u));
  const std::uint32_t warp_seed = hash3(p.seed, 0xA11Eu, 7u);
  const double warp_ox = 16.0 + 64.0 * unit(hash3(warp_seed, 5u, 6u));
  const double warp_oy = 16.0 + 64.0 * unit(hash3(warp_seed, 7u, 8u));
  // Each octave doubles the frequency and rotates the domain by atan(3/4)
  // (an exactly representable rotation: c = 0.8, s = 0.6).
  constexpr double kRotC = 0.8, kRotS = 0.6;
  const double w = p.ridge_weight;

  Heightfield hf;
  hf.width = hf.height = size;
  hf.spacing_x_m = hf.spacing_y_m = p.spacing_m;
  hf.heights.resize(std::size_t(size) * std::size_t(size));

  double lo = 1e300, hi = -1e300;
  for (int j = 0; j < size; ++j) {
    const double y = double(j) * inv_n;
    for (int i = 0; i < size; ++i) {
      const double x = double(i) * inv_n;
      // Domain warp: bend the ridge lines with a low-frequency field.
      const double wx = gradient_noise(x * kWarpFrequency + warp_ox, y * kWarpFrequency + warp_oy,
                                       warp_seed);
      const double wy = gradient_noise(x * kWarpFrequency + warp_oy, y * kWarpFrequency + warp_ox,
                                       warp_seed ^ 0x9E3779B9u);
      double px = (x + kWarpAmount * wx) * kBaseFrequency;
      double py = (y + kWarpAmount * wy) * kBaseFrequency;
      double fbm = 0.0, ridged = 0.0, amp = 1.0, amp_sum = 0.0, weight = 1.0;
      for (int o = 0; o < p.octaves; ++o) {
        const Octave& oc = oct[std::size_t(o)];
        const double nv = gradient_noise(px + oc.ox, py + oc.oy, oc.seed);
        fbm += amp * nv;
        double r = 1.0 - std::fabs(nv);
        r *= r;
        r *= weight;
        weight = std::clamp(r * 2.0, 0.0, 1.0);
        ridged += amp * r;
        amp_sum += amp;
        amp *= kGain;
        const double rx = kRotC * px - kRotS * py, ry = kRotS * px + kRotC * py;
        px = 2.0 * rx;
        py = 2.0 * ry;
      }
      const double fbm01 = 0.5 + 0.5 * (fbm / amp_sum);
      const double ridged01 = ridged / amp_sum;
      const double mountain = (1.0 - w) * fbm01 + w * ridged01;
      // Macro relief: a smooth two-octave field decides where the mountain
      // ranges are; between them the detail fades into broad valleys.
      const double m1 = gradient_noise(x * kMacroFrequency + macro_ox, y * kMacroFrequency + macro_oy,
                                       macro_seed);
      const double m2 = gradient_noise(2.0 * kMacroFrequency * (kRotC * x - kRotS * y) + macro_oy,
                                       2.0 * kMacroFrequency * (kRotS * x + kRotC * y) + macro_ox,
                                       macro_seed ^ 0x51ED270Bu);
      const double macro = 0.5 + 0.5 * ((m1 + 0.5 * m2) * (1.0 / 1.5));
      const double mask = smoothstep(kMaskLo, kMaskHi, macro);
      const double h = kMacroAmount * macro + (kPlainDetail + (1.0 - kPlainDetail) * mask) * mountain +
                       kTiltAmount * (tilt[0] * (x - 0.5) + tilt[1] * (y - 0.5));
      // Stored as float until normalised: half the memory of a double buffer
      // (16385^2 samples is 1 GiB as float).
      const float hf32 = float(h);
      hf.heights[std::size_t(j) * size + i] = hf32;
      lo = std::min(lo, double(hf32));
      hi = std::max(hi, double(hf32));
    }
  }

  // Normalise to [0, 1], flatten the low ground (t' = 0.4 t + 0.6 t^2 keeps 0
  // and 1 fixed), then scale into [base, base + relief].
  const double range = hi - lo;
  const double inv_range = range > 0 ? 1.0 / range : 0.0;
  const float fmin = float(p.base_m), fmax = float(p.base_m + p.relief_m);
  for (float& v : hf.heights) {
    const double t = std::clamp((double(v) - lo) * inv_range, 0.0, 1.0);
    const double shaped = t * (kShapeLin + (1.0 - kShapeLin) * t);
    v = std::clamp(float(p.base_m + p.relief_m * shaped), fmin, fmax);
  }
  hf.nodata_count = 0;
  hf.source = "synthetic(seed=" + std::to_string(p.seed) + ",size=" + std::to_string(size) + ")";
  hf.finalize_stats();
  return hf;
}

}  // namespace ig::terrain
