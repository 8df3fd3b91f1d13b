// Benchmark for the host services' per-frame answering (tools/ig/host_services.h).
//
//   bench_host_services [DEM_FILE] [--frames N] [--hot N] [--los N]
//
// The load of docs/results.md "Host services" in-process, without
// sockets or rendering: every frame one CIGI host datagram with N HAT/HOT
// requests (a third each HAT, HOT, extended) and N extended LOS requests
// (half segments, half vectors, 5-20 km, 2000 m above the terrain, 5-30°
// down; tools/load/cigi_request_mix.h, the same generator as the loopback
// host cigi_query_host --bench) is taken and answered. Between frames 128 MB are written, as the
// renderer does, so the DEM is out of the caches as it is in ig serve. Prints
// milliseconds per frame (mean / median / p95 / max) for take(), answer_frame()
// (what summary.json reports as answer_ms) and encoding the responses,
// HAT/HOT points over the whole DEM and within 2 km of the ownship, and
// HAT/HOT alone and LOS alone. DEM_FILE defaults to
// $IG_DEM_DIR/sierra_nevada_3arcsec_4097.tif. Single-threaded; answer_frame's
// process CPU time is printed beside its wall time.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "session/host_services.h"
#include "io/wire/cigi.h"
#include "io/wire/cigi_queries.h"
#include "load/cigi_request_mix.h"
#include "session/scene_setup.h"
#include "stats/timing.h"
#include "terrain/dem_loader.h"
#include "terrain/earth_curvature.h"
#include "terrain/height_pyramid.h"

namespace {

using namespace ig::io::wire;
using Clock = ig::stats::WallClock;
using ig::stats::ms_since;
using ig::stats::process_cpu_ms;
using ig::load::CigiRequestMix;
using Load = ig::load::RequestLoad;

// What rendering a frame does to the caches: writes far more than they hold.
class CacheFlusher {
 public:
  void operator()() {
    ++pass_;
    for (std::size_t k = 0; k < buf_.size(); k += 16) buf_[k] = pass_;
  }

 private:
  std::vector<std::uint32_t> buf_ = std::vector<std::uint32_t>(std::size_t(32) << 20);  // 128 MB
  std::uint32_t pass_ = 0;
};

struct Figures {
  std::vector<double> take_ms, answer_ms, answer_cpu_ms, encode_ms;
};

void print_row(const char* name, std::vector<double> v) {
  std::sort(v.begin(), v.end());
  double sum = 0.0;
  for (double x : v) sum += x;
  std::printf("  %-14s mean %.3f  median %.3f  p95 %.3f  max %.3f ms\n", name, sum / double(v.size()),
              v[v.size() / 2], v[std::min(v.size() - 1, std::size_t(0.95 * double(v.size())))], v.back());
}

Figures run(const ig::terrain::Heightfield& hf, const ig::terrain::HeightPyramid& pyramid, const Load& load,
            int frames, bool flush) {
  ig::session::HostServices services(hf, ig::terrain::kEarthRadiusM, ig::session::geodetic_placer(hf),
                                     ig::session::local_to_geodetic(hf), {}, &pyramid);
  CigiRequestMix maker(hf);
  ig::io::Pose own;
  own.position = maker.ownship_at();
  CacheFlusher flush_caches;
  const std::array<std::uint8_t, kCigiStartOfFrameSize> sof{};
  Figures f;
  for (int k = 1; k <= frames; ++k) {
    const std::vector<std::uint8_t> d = maker.datagram(std::uint32_t(k), load, {});
    if (flush) flush_caches();
    auto t0 = Clock::now();
    services.take(d);
    f.take_ms.push_back(ms_since(t0));
    t0 = Clock::now();
    const double cpu0 = process_cpu_ms();
    const std::vector<CigiResponse> answers = services.answer_frame(own);
    f.answer_ms.push_back(ms_since(t0));
    f.answer_cpu_ms.push_back(process_cpu_ms() - cpu0);
    t0 = Clock::now();
    std::vector<std::uint8_t> out(sof.begin(), sof.end());
    for (const CigiResponse& r : answers) append_cigi_response(r, false, out);
    f.encode_ms.push_back(ms_since(t0));
    if (answers.size() != std::size_t(load.hot + load.los)) std::printf("  (only %zu answers)\n", answers.size());
  }
  return f;
}

void report(const char* title, const Figures& f) {
  std::printf("%s\n", title);
  print_row("take", f.take_ms);
  print_row("answer_frame", f.answer_ms);
  print_row("  its CPU", f.answer_cpu_ms);
  print_row("encode", f.encode_ms);
}

}  // namespace

int main(int argc, char** argv) {
  std::string path;
  int frames = 300;
  Load load;
  for (int k = 1; k < argc; ++k) {
    const std::string s = argv[k];
    if (s == "--frames" && k + 1 < argc) frames = std::max(1, std::atoi(argv[++k]));
    else if (s == "--hot" && k + 1 < argc) load.hot = std::max(0, std::atoi(argv[++k]));
    else if (s == "--los" && k + 1 < argc) load.los = std::max(0, std::atoi(argv[++k]));
    else path = s;
  }
  if (path.empty()) {
    const char* dir = std::getenv("IG_DEM_DIR");
    if (!dir) {
      std::fprintf(stderr, "bench_host_services: give a DEM file or set IG_DEM_DIR\n");
      return 2;
    }
    path = std::string(dir) + "/sierra_nevada_3arcsec_4097.tif";
  }
  const ig::terrain::Heightfield hf = ig::terrain::load_dem(path);
  const ig::terrain::HeightPyramid pyramid(hf);
  std::printf("%s: %dx%d samples, %.0f x %.0f m spacing; %d frames of %d HAT/HOT + %d LOS, 128 MB written "
              "between frames (cold caches) unless warm\n",
              path.c_str(), hf.width, hf.height, hf.spacing_x_m, hf.spacing_y_m, frames, load.hot, load.los);
  const Load whole = load, near{load.hot, load.los, 2000.0};
  report("whole DEM, cold caches:", run(hf, pyramid, whole, frames, true));
  report("within 2 km, cold caches:", run(hf, pyramid, near, frames, true));
  report("whole DEM, warm caches:", run(hf, pyramid, whole, frames, false));
  report("HAT/HOT alone, whole DEM, cold:", run(hf, pyramid, Load{load.hot, 0, 0.0}, frames, true));
  report("HAT/HOT alone, within 2 km, cold:", run(hf, pyramid, Load{load.hot, 0, 2000.0}, frames, true));
  report("LOS alone, cold:", run(hf, pyramid, Load{0, load.los, 0.0}, frames, true));
  report("LOS alone, warm:", run(hf, pyramid, Load{0, load.los, 0.0}, frames, false));
  return 0;
}
