// Benchmark: time to load a DEM from disk (GDAL) and to upload its scene
// textures (headless GL: R32F heights, their central differences, ground
// detail). Prints figures; asserts nothing.
//   build/bin/bench_dem_load [FILE] [--repeat N]
// FILE defaults to $IG_DEM_DIR/sierra_nevada_3arcsec_4097.tif.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "gl/gl_context.h"
#include "render/terrain_scene.h"
#include "stats/frame_log.h"
#include "bench_args.h"
#include "terrain/dem_loader.h"

int main(int argc, char** argv) {
  return ig::bench::run_dem_bench(argc, argv, "bench_dem_load", [](const std::string& path, int repeat) {
    std::vector<double> load_ms, upload_ms;
    ig::terrain::Heightfield hf;
    for (int k = 0; k < repeat; ++k) load_ms.push_back(ig::bench::time_ms([&] { hf = ig::terrain::load_dem(path); }));
    auto ctx = ig::gl::create_headless_context();
    for (int k = 0; k < repeat; ++k) {
      ig::render::TerrainScene scene(hf, ig::render::ShadingParams{});
      upload_ms.push_back(scene.upload_ms());
    }
    const auto l = ig::stats::percentiles(load_ms), u = ig::stats::percentiles(upload_ms);
    std::printf("dem: %s (%dx%d, %.1f MiB as float32)\n", path.c_str(), hf.width, hf.height,
                hf.heights.size() * 4.0 / (1024 * 1024));
    std::printf("renderer: %s | %s\n", ctx->gl_renderer().c_str(), ctx->gl_version().c_str());
    std::printf("load (GDAL read + flip + stats), %d runs: median %.1f ms, min %.1f ms, max %.1f ms\n", repeat,
                l.median, *std::min_element(load_ms.begin(), load_ms.end()), l.max);
    std::printf("scene textures upload (R32F heights, RG16F central differences, ground detail; + glFinish), %d runs: "
                "median %.1f ms, max %.1f ms\n",
                repeat, u.median, u.max);
    return 0;
  });
}
