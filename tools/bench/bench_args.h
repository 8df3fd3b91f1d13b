#pragma once
// Shared argument handling of the DEM benchmarks: [FILE] [--repeat N], FILE
// defaulting to $IG_DEM_DIR/sierra_nevada_3arcsec_4097.tif.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

namespace ig::bench {

struct DemBenchArgs {
  std::string path;
  int repeat = 5;
};

// nullopt (after a message on stderr) when there is neither a file nor IG_DEM_DIR.
inline std::optional<DemBenchArgs> parse_dem_bench_args(int argc, char** argv, const char* name) {
  DemBenchArgs a;
  for (int k = 1; k < argc; ++k) {
    const std::string s = argv[k];
    if (s == "--repeat" && k + 1 < argc) a.repeat = std::max(1, std::atoi(argv[++k]));
    else a.path = s;
  }
  if (a.path.empty()) {
    const char* dir = std::getenv("IG_DEM_DIR");
    if (!dir) {
      std::fprintf(stderr, "%s: give a DEM file or set IG_DEM_DIR\n", name);
      return std::nullopt;
    }
    a.path = std::string(dir) + "/sierra_nevada_3arcsec_4097.tif";
  }
  return a;
}

}  // namespace ig::bench
