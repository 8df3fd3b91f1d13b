// Benchmark for terrain ray casts (visual/terrain/ray_cast.h).
//
//   bench_ray_cast [samples_per_side=4097] [rays_per_set=20000] [dda_rays=300]
//
// Builds a deterministic fractal heightfield (value noise, 30 m spacing) in
// memory, then prints plain text: pyramid build time, and mean / median /
// p99 microseconds per cast_ray for (a) steep look-down rays, (b) grazing rays
// near the horizon from 100 m above ground, (c) sky rays (nearly all miss), plus the
// naive cell-by-cell DDA (cast_ray_dda) on the first dda_rays rays of (b) and
// the pyramid's speed-up on the same rays; (d) is (b) as coherent fans of
// 1000 rays from one point, for the effect of warm caches. Single-threaded.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "terrain/height_pyramid.h"
#include "terrain/heightfield.h"
#include "terrain/ray_cast.h"

namespace {

using Clock = std::chrono::steady_clock;
using ig::terrain::Heightfield;
using ig::terrain::HeightPyramid;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Integer hash of a lattice point -> [-1, 1].
double lattice(std::int64_t x, std::int64_t y, std::uint32_t seed) {
  std::uint64_t h = static_cast<std::uint64_t>(x) * 0x9E3779B97F4A7C15ull ^
                    static_cast<std::uint64_t>(y) * 0xC2B2AE3D27D4EB4Full ^ (std::uint64_t(seed) << 32);
  h ^= h >> 33;
  h *= 0xFF51AFD7ED558CCDull;
  h ^= h >> 33;
  h *= 0xC4CEB9FE1A85EC53ull;
  h ^= h >> 33;
  return double(h >> 11) * (2.0 / 9007199254740992.0) - 1.0;
}

double value_noise(double x, double y, std::uint32_t seed) {
  const double fx = std::floor(x), fy = std::floor(y);
  const auto ix = static_cast<std::int64_t>(fx), iy = static_cast<std::int64_t>(fy);
  double u = x - fx, v = y - fy;
  u = u * u * (3 - 2 * u);
  v = v * v * (3 - 2 * v);
  const double a = lattice(ix, iy, seed), b = lattice(ix + 1, iy, seed);
  const double c = lattice(ix, iy + 1, seed), d = lattice(ix + 1, iy + 1, seed);
  return (a + (b - a) * u) + ((c + (d - c) * u) - (a + (b - a) * u)) * v;
}

// Mountains: 9 octaves from a 1024-sample wavelength down to 4 samples,
// ridged at the large scales so there are sharp crests; 0..~2600 m.
Heightfield make_terrain(int n, double spacing) {
  Heightfield hf;
  hf.width = hf.height = n;
  hf.spacing_x_m = hf.spacing_y_m = spacing;
  hf.heights.resize(static_cast<std::size_t>(n) * n);
  hf.source = "bench_ray_cast fractal " + std::to_string(n) + "x" + std::to_string(n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      double h = 0, amp = 900, freq = 1.0 / 1024;
      for (int o = 0; o < 9; ++o) {
        const double nv = value_noise(i * freq, j * freq, 17u + o);
        h += amp * (o < 3 ? 1 - 2 * std::abs(nv) : nv);
        amp *= 0.5;
        freq *= 2;
      }
      hf.ref(i, j) = float(std::max(0.0, h + 900));
    }
  hf.finalize_stats();
  return hf;
}

struct Ray {
  glm::dvec3 o, d;
};

struct Summary {
  double mean_us = 0, median_us = 0, p99_us = 0;
  int hits = 0;
  double nodes = 0, cells = 0;  // mean per ray (cells only for the DDA)
};

Summary run(const std::vector<Ray>& rays, bool dda, const Heightfield& hf, const HeightPyramid& pyr,
            std::vector<std::optional<double>>* ts = nullptr, std::vector<double>* per_ray_us = nullptr) {
  std::vector<double> us;
  us.reserve(rays.size());
  Summary s;
  for (const Ray& r : rays) {
    ig::terrain::RayCastStats st;
    const auto t0 = Clock::now();
    const auto hit = dda ? ig::terrain::cast_ray_dda(hf, r.o, r.d)
                         : ig::terrain::cast_ray(hf, pyr, r.o, r.d, std::numeric_limits<double>::infinity(), st);
    us.push_back(seconds_since(t0) * 1e6);
    s.nodes += st.nodes_tested;
    s.cells += st.cells_tested;
    if (hit) ++s.hits;
    if (ts) ts->push_back(hit ? std::optional<double>(hit->t) : std::nullopt);
  }
  if (per_ray_us) *per_ray_us = us;
  s.nodes /= std::max<std::size_t>(1, rays.size());
  s.cells /= std::max<std::size_t>(1, rays.size());
  double sum = 0;
  for (double u : us) sum += u;
  s.mean_us = us.empty() ? 0 : sum / us.size();
  std::sort(us.begin(), us.end());
  if (!us.empty()) {
    s.median_us = us[us.size() / 2];
    s.p99_us = us[std::min(us.size() - 1, static_cast<std::size_t>(us.size() * 0.99))];
  }
  return s;
}

void print(const char* name, const std::vector<Ray>& rays, const Summary& s) {
  std::printf("%-38s rays=%zu hits=%d mean=%.2f us median=%.2f us p99=%.2f us", name, rays.size(), s.hits,
              s.mean_us, s.median_us, s.p99_us);
  if (s.nodes > 0) std::printf(" (%.1f nodes, %.1f cells per ray)", s.nodes, s.cells);
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::max(2, std::atoi(argv[1])) : 4097;
  const int rays_per_set = argc > 2 ? std::max(1, std::atoi(argv[2])) : 20000;
  const int dda_rays = argc > 3 ? std::max(1, std::atoi(argv[3])) : 300;
  const double spacing = 30.0;

  auto t0 = Clock::now();
  const Heightfield hf = make_terrain(n, spacing);
  std::printf("heightfield %dx%d spacing %.0f m extent %.1f km, heights %.1f..%.1f m, generated in %.2f s\n", n, n,
              spacing, hf.extent_x_m() / 1000, hf.min_m, hf.max_m, seconds_since(t0));

  // Pyramid build: best and median of 5.
  std::vector<double> build_ms;
  HeightPyramid pyr;
  for (int k = 0; k < 5; ++k) {
    t0 = Clock::now();
    pyr = HeightPyramid(hf);
    build_ms.push_back(seconds_since(t0) * 1e3);
  }
  std::sort(build_ms.begin(), build_ms.end());
  std::printf("pyramid build: median %.1f ms, best %.1f ms (%d levels, %.1f MB)\n", build_ms[2], build_ms[0],
              pyr.num_levels(), pyr.memory_bytes() / 1e6);

  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  const double ex = hf.extent_x_m(), ey = hf.extent_y_m();
  const double deg = M_PI / 180;
  auto random_origin = [&](double agl_lo, double agl_hi) {
    const double x = ex * (0.1 + 0.8 * u01(rng)), y = ey * (0.1 + 0.8 * u01(rng));
    return glm::dvec3{x, y, hf.sample_surface(x, y) + agl_lo + (agl_hi - agl_lo) * u01(rng)};
  };
  auto direction = [&](double elev_deg, double az_rad) {
    const double el = elev_deg * deg;
    return glm::dvec3{std::cos(az_rad) * std::cos(el), std::sin(az_rad) * std::cos(el), std::sin(el)};
  };
  auto make_rays = [&](double agl_lo, double agl_hi, double elev_lo_deg, double elev_hi_deg) {
    std::vector<Ray> rays;
    rays.reserve(rays_per_set);
    for (int k = 0; k < rays_per_set; ++k) {
      const glm::dvec3 o = random_origin(agl_lo, agl_hi);
      const double el = elev_lo_deg + (elev_hi_deg - elev_lo_deg) * u01(rng);
      rays.push_back({o, direction(el, 2 * M_PI * u01(rng))});
    }
    return rays;
  };
  const std::vector<Ray> steep = make_rays(300, 3000, -90, -30);
  const std::vector<Ray> grazing = make_rays(100, 100, -1.0, 0.25);
  const std::vector<Ray> sky = make_rays(100, 100, 15, 90);
  // Coherent variant of (b): fans of 1000 rays around each of a few points
  // (like a sensor sweep), so the pyramid's upper levels stay in cache.
  std::vector<Ray> fan;
  glm::dvec3 fan_origin{};
  for (int k = 0; k < rays_per_set; ++k) {
    if (k % 1000 == 0) fan_origin = random_origin(100, 100);
    fan.push_back({fan_origin, direction(-1.0 + 1.25 * u01(rng), 2 * M_PI * (k % 1000) / 1000.0)});
  }

  run(steep, false, hf, pyr);  // warm caches
  print("(a) steep look-down, pyramid", steep, run(steep, false, hf, pyr));
  print("(b) grazing 100 m AGL, pyramid", grazing, run(grazing, false, hf, pyr));
  print("(c) sky 15..90 deg, pyramid", sky, run(sky, false, hf, pyr));
  print("(d) grazing fans (coherent), pyramid", fan, run(fan, false, hf, pyr));

  const std::vector<Ray> sub(grazing.begin(), grazing.begin() + std::min<std::size_t>(dda_rays, grazing.size()));
  std::vector<std::optional<double>> t_dda;
  std::vector<double> us_dda, us_pyr;
  const Summary sd = run(sub, true, hf, pyr, &t_dda, &us_dda);
  std::vector<std::optional<double>> t_pyr_sub;
  const Summary sp = run(sub, false, hf, pyr, &t_pyr_sub, &us_pyr);
  print("(b) grazing subset, naive DDA", sub, sd);
  print("(b) grazing subset, pyramid", sub, sp);
  int disagree = 0;
  for (std::size_t k = 0; k < sub.size(); ++k) {
    const auto& a = t_pyr_sub[k];
    const auto& b = t_dda[k];
    if (a.has_value() != b.has_value() || (a && std::abs(*a - *b) > 1e-6 * std::max(1.0, *a))) ++disagree;
  }
  std::printf("speed-up pyramid vs naive DDA on the same %zu grazing rays: mean %.1fx, median %.1fx "
              "(results differ on %d rays)\n",
              sub.size(), sd.mean_us / sp.mean_us, sd.median_us / sp.median_us, disagree);
  // Long rays (hit beyond 10 km, or miss): where the pyramid's skipping pays.
  double long_dda = 0, long_pyr = 0;
  int n_long = 0;
  for (std::size_t k = 0; k < sub.size(); ++k)
    if (!t_dda[k] || *t_dda[k] > 10000) {
      ++n_long;
      long_dda += us_dda[k];
      long_pyr += us_pyr[k];
    }
  if (n_long > 0)
    std::printf("  of which %d long rays (hit beyond 10 km or miss): naive DDA mean %.2f us, pyramid mean %.2f us, "
                "speed-up %.1fx\n",
                n_long, long_dda / n_long, long_pyr / n_long, long_dda / long_pyr);
  return disagree == 0 ? 0 : 1;
}
