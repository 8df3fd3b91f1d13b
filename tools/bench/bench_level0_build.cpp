// Benchmark: time to build the Level0 static ROAM mesh (error precompute +
// greedy refinement + output) at several triangle budgets. Prints figures;
// asserts nothing.
//   build/bin/bench_level0_build [FILE] [--repeat N]
// FILE defaults to $IG_DEM_DIR/sierra_nevada_3arcsec_4097.tif.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "lod/roam_level0_mesh.h"
#include "bench_args.h"
#include "terrain/dem_loader.h"

int main(int argc, char** argv) {
  return ig::bench::run_dem_bench(argc, argv, "bench_level0_build", [](const std::string& path, int repeat) {
    const ig::terrain::Heightfield hf = ig::terrain::load_dem(path);
    std::printf("dem: %s (%dx%d, spacing %.1f x %.1f m, heights %.0f..%.0f m)\n", path.c_str(), hf.width,
                hf.height, hf.spacing_x_m, hf.spacing_y_m, hf.min_m, hf.max_m);
    {
      std::vector<double> ms;
      for (int k = 0; k < repeat; ++k) {
        ig::lod::Level0ErrorGrid g;
        ms.push_back(ig::bench::time_ms([&] { g = ig::lod::compute_level0_errors(hf); }));
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
  });
}
