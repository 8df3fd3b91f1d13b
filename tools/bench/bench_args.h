#pragma once
// Shared by the DEM benchmarks: the arguments [FILE] [--repeat N], FILE
// defaulting to $IG_DEM_DIR/sierra_nevada_3arcsec_4097.tif, the main around
// a benchmark's body, and timing a call.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
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

// A DEM benchmark's main: body(path, repeat) with the parsed arguments, its
// exit status; 2 without a DEM, 1 after "NAME: what" on stderr for anything
// the body throws.
template <class Body>
int run_dem_bench(int argc, char** argv, const char* name, Body body) {
  const auto args = parse_dem_bench_args(argc, argv, name);
  if (!args) return 2;
  try {
    return body(args->path, args->repeat);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", name, e.what());
    return 1;
  }
}

// The wall time f() takes, in milliseconds (steady clock).
template <class F>
double time_ms(F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace ig::bench
