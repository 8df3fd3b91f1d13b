// Benchmark: time to build the Level0 static ROAM mesh (error precompute +
// greedy refinement + output) at several triangle budgets. Prints figures;
// asserts nothing.
//   build/bin/bench_level0_build [FILE] [--repeat N]
// FILE defaults to $IG_DEM_DIR/sierra_nevada_3arcsec_4097.tif.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "lod/roam_level0_mesh.h"
#include "bench_args.h"
#include "terrain/dem_loader.h"

int main(int argc, char** argv) {
  const auto args = ig::bench::parse_dem_bench_args(argc, argv, "bench_level0_build");
  if (!args) return 2;
  const std::string& path = args->path;
  const int repeat = args->repeat;
  try {
    using Clock = std::chrono::steady_clock;
    const ig::terrain::Heightfield hf = ig::terrain::load_dem(path);
    std::printf("dem: %s (%dx%d, spacing %.1f x %.1f m, heights %.0f..%.0f m)\n", path.c_str(), hf.width,
                hf.height, hf.spacing_x_m, hf.spacing_y_m, hf.min_m, hf.max_m);
    {
      std::vector<double> ms;
      for (int k = 0; k < repeat; ++k) {
        const auto t0 = Clock::now();
        const auto g = ig::lod::compute_level0_errors(hf);
        ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
        if (g.side == 0) return 1;
      }
      std::sort(ms.begin(), ms.end());
      std::printf("error precompute only, %d runs: median %.1f ms, min %.1f ms\n", repeat, ms[ms.size() / 2],
                  ms.front());
    }
    for (int budget : {2048, 8192, 32768}) {
      std::vector<double> ms;
      ig::lod::Level0Mesh m;
      for (int k = 0; k < repeat; ++k) {
        m = ig::lod::build_level0_mesh(hf, {budget, 0.0});
        ms.push_back(m.build_ms);
      }
      std::sort(ms.begin(), ms.end());
      std::printf("budget %6d: %6d triangles, %6zu vertices, max error %8.2f m, build median %.1f ms "
                  "(min %.1f, max %.1f, %d runs)\n",
                  budget, m.triangle_count, m.positions.size(), m.max_error_m, ms[ms.size() / 2], ms.front(),
                  ms.back(), repeat);
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_level0_build: %s\n", e.what());
    return 1;
  }
}
