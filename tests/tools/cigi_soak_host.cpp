// cigi_query_host --soak (tests/tools/cigi_query_host.cpp): a CIGI host for
// the soak benchmark and test.
// --soak: a host in its own time against an IG in its own time (not
// synchronous), as a simulator runs: for S seconds of the steady clock after
// the IG's first Start Of Frame, RATE datagrams a second (default 60), each
// the ownship's Entity Control (with its timestamp) and HOT HAT/HOT and LOS
// requests (tools/load/cigi_request_mix.h) within SPREAD_M (default 5000)
// of the ownship. The ownship flies a circle clockwise at SPEED m/s
// (default 250; 0 hovers at the circle's north point), banked for the turn, AGL metres above the highest surface
// under it and up to 3 km ahead; the circle's centre and radius default to
// the terrain's centre and a quarter of its smaller side (--radius: that
// centre, this radius). TERRAIN is a DEM
// or a scenario file (its terrain: a DEM, paged by its memory budget, or
// generated). Reads the IG's datagrams without waiting and prints what came
// back (tools/bench/soak.sh). No checks: it drives the IG, the caller looks.
//
#include "cigi_soak_host.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <thread>
#include <variant>
#include <vector>
#include <glm/geometric.hpp>
#include "io/filter/geodesy.h"
#include "io/net/udp_socket.h"
#include "io/pose.h"
#include "io/scenario.h"
#include "io/wire/cigi.h"
#include "io/wire/cigi_queries.h"
#include "io/wire/cigi_views.h"
#include "io/wire/native_query.h"
#include "load/cigi_request_mix.h"
#include "session/scene_setup.h"
#include "terrain/dem_loader.h"
#include "terrain/earth_curvature.h"

namespace {

using namespace ig::io::wire;
using glm::dvec3;

// A DEM file, or a scenario's terrain (its DEM with its load options, or its generator).
ig::terrain::Heightfield load_host_terrain(const std::string& path) {
  if (path.size() > 5 && path.substr(path.size() - 5) == ".json")
    return ig::session::load_terrain(ig::io::load_scenario(path).terrain);
  return ig::terrain::load_dem(path);
}

struct SoakOptions {
  int hot = 100, los = 10;
  double duration_s = 0.0, rate_hz = 60.0, spread_m = 5000.0, speed_mps = 250.0, agl_m = 150.0;
  std::optional<glm::dvec3> circle;  // lat deg, lon deg, radius m
  std::optional<double> radius_m;    // about the terrain's centre
};

int soak(const ig::terrain::Heightfield& hf, ig::io::net::UdpSender& to_ig, ig::io::net::UdpReceiver& replies,
         const SoakOptions& o) {
  ig::load::CigiRequestMix mix(hf, 15);
  const ig::load::RequestLoad load{o.hot, o.los, o.spread_m, o.spread_m};
  const auto grid = ig::io::geo::GeographicGrid::make(hf.georef->grid_to_crs, hf.spacing_x_m, hf.spacing_y_m);
  dvec3 centre(0.5 * hf.extent_x_m(), 0.5 * hf.extent_y_m(), 0.0);
  double radius = 0.25 * std::min(hf.extent_x_m(), hf.extent_y_m());
  if (o.circle) {
    centre = grid->to_local({o.circle->x, o.circle->y, 0.0});
    radius = o.circle->z;
  } else if (o.radius_m) {
    radius = *o.radius_m;
  }
  const double bank_deg = std::atan(o.speed_mps * o.speed_mps / (9.80665 * radius)) * 180.0 / M_PI;
  // Clockwise from the circle's north point: phi clockwise from north about the centre.
  auto place = [&](double t_s, PoseMessage& m, dvec3& at) {
    const double phi = o.speed_mps * t_s / radius;
    at = centre + radius * dvec3(std::sin(phi), std::cos(phi), 0.0);
    const dvec3 ahead(std::cos(phi), -std::sin(phi), 0.0);
    double ground = -1e9;
    for (double d : {0.0, 500.0, 1000.0, 2000.0, 3000.0}) {
      const dvec3 q = at + d * ahead;
      const double x = std::clamp(q.x, 0.0, hf.extent_x_m()), y = std::clamp(q.y, 0.0, hf.extent_y_m());
      ground = std::max(ground, hf.sample_surface(x, y));
    }
    at.z = ground + o.agl_m;
    m.frame = PoseMessage::Frame::Geodetic;
    m.position = mix.geodetic(at);
    m.heading_deg = std::fmod(phi * 180.0 / M_PI + 90.0, 360.0);
    m.pitch_deg = -3.0;
    m.roll_deg = bank_deg;
    m.sender_time_s = t_s;
    m.has_sender_time = true;
  };

  std::uint64_t sofs = 0, hot_answers = 0, hot_invalid = 0, los_answers = 0, los_invalid = 0, undecodable = 0;
  std::uint32_t first_ig_frame = 0, last_ig_frame = 0, last_echoed = 0;
  auto read_replies = [&] {
    return replies.poll(
        [&](std::span<const std::uint8_t> dg, double, const sockaddr_in&) {
          const auto sof = decode_cigi_start_of_frame(dg);
          if (!sof.sof) return;
          if (sofs++ == 0) first_ig_frame = sof.sof->ig_frame;
          last_ig_frame = sof.sof->ig_frame;
          last_echoed = sof.sof->last_host_frame;
          const auto r = decode_cigi_responses(dg);
          if (!r) {
            ++undecodable;
            return;
          }
          for (const auto& a : *r) {
            if (const auto* h = std::get_if<HatHotResponse>(&a)) {
              ++hot_answers;
              hot_invalid += !h->valid;
            } else {
              ++los_answers;
              los_invalid += !std::get<LosResponse>(a).valid;
            }
          }
        },
        4096);
  };
  // Starts with the IG: its first Start Of Frame (it sends one every frame).
  while (sofs == 0) {
    replies.wait_readable(1.0);
    read_replies();
  }
  using clock = std::chrono::steady_clock;
  const auto period = std::chrono::duration_cast<clock::duration>(std::chrono::duration<double>(1.0 / o.rate_hz));
  const auto start = clock::now();
  auto tick = start;
  std::uint64_t sent = 0, send_failed = 0, late = 0;
  std::uint32_t last_sent = 0;
  auto steady_s = [](clock::time_point t) { return std::chrono::duration<double>(t.time_since_epoch()).count(); };
  std::printf("soak host: the IG is up (IG frame %u), sending for %g s from steady_s %.3f\n", first_ig_frame,
              o.duration_s, steady_s(start));
  std::fflush(stdout);
  for (std::uint32_t k = 1;; ++k) {
    const double t = std::chrono::duration<double>(tick - start).count();
    if (t >= o.duration_s) break;
    last_sent = k;
    PoseMessage ownship;
    dvec3 at;
    place(t, ownship, at);
    if (to_ig.send(mix.datagram(k, load, ownship, at))) ++sent;
    else ++send_failed;
    read_replies();
    tick += period;
    const auto now = clock::now();
    if (now > tick + period) {  // more than a frame behind: go on from now, as a host's frame loop would
      ++late;
      tick = now;
    }
    std::this_thread::sleep_until(tick);
  }
  const auto end = clock::now();
  const double elapsed = std::chrono::duration<double>(end - start).count();
  // The answers to the last datagram come with the Start Of Frame that
  // echoes it (within 2 s; the IG sends one every frame).
  const auto drain_until = clock::now() + std::chrono::seconds(2);
  while (last_echoed < last_sent && clock::now() < drain_until) {
    replies.wait_readable(0.1);
    read_replies();
  }
  const double requests = double(sent) * (o.hot + o.los);
  std::printf("soak host: %llu datagrams in %.1f s (%.1f a second), %llu not sent, %llu ticks more than a frame late; "
              "%d HAT/HOT + %d LOS requests each within %.0f m of the ownship (circle radius %.0f m, %.0f m/s, "
              "bank %.1f deg, %.0f m above the ground ahead); the last sent at steady_s %.3f\n",
              (unsigned long long)sent, elapsed, sent / elapsed, (unsigned long long)send_failed,
              (unsigned long long)late, o.hot, o.los, o.spread_m, radius, o.speed_mps, bank_deg, o.agl_m,
              steady_s(end));
  std::printf("soak host: IG Start Of Frames %llu (IG frames %u..%u), %llu undecodable; answers: HAT/HOT %llu "
              "(%llu invalid), LOS %llu (%llu invalid), %.4f of the requests\n",
              (unsigned long long)sofs, first_ig_frame, last_ig_frame, (unsigned long long)undecodable,
              (unsigned long long)hot_answers, (unsigned long long)hot_invalid, (unsigned long long)los_answers,
              (unsigned long long)los_invalid, requests > 0 ? double(hot_answers + los_answers) / requests : 0.0);
  return 0;
}

}  // namespace

int soak_main(int argc, char** argv) {
  auto usage = [] {
    std::fprintf(stderr, "usage: cigi_query_host TERRAIN IG_ADDR:PORT LISTEN_ADDR:PORT --soak HOT LOS --duration S "
                         "[--rate HZ] [--spread M] [--circle LAT,LON,RADIUS_M | --radius M] [--speed MPS] [--agl M]\n");
    return 2;
  };
  if (argc < 7) return usage();
  SoakOptions o;
  o.hot = std::stoi(argv[5]);
  o.los = std::stoi(argv[6]);
  for (int k = 7; k < argc; k += 2) {
    if (k + 1 >= argc) return usage();
    const std::string opt = argv[k], v = argv[k + 1];
    if (opt == "--duration") o.duration_s = std::stod(v);
    else if (opt == "--rate") o.rate_hz = std::stod(v);
    else if (opt == "--spread") o.spread_m = std::stod(v);
    else if (opt == "--speed") o.speed_mps = std::stod(v);
    else if (opt == "--agl") o.agl_m = std::stod(v);
    else if (opt == "--radius") o.radius_m = std::stod(v);
    else if (opt == "--circle") {
      double lat, lon, r;
      if (std::sscanf(v.c_str(), "%lf,%lf,%lf", &lat, &lon, &r) != 3 || !(r > 0)) return usage();
      o.circle = dvec3(lat, lon, r);
    } else return usage();
  }
  if (!(o.duration_s > 0) || !(o.rate_hz > 0) || !(o.speed_mps >= 0) || o.hot < 0 || o.los < 0 || (o.radius_m && !(*o.radius_m > 0)))
    return usage();
  const ig::terrain::Heightfield hf = load_host_terrain(argv[1]);
  ig::io::net::UdpSender to_ig(argv[2]);
  ig::io::net::UdpReceiver replies(argv[3]);
  return soak(hf, to_ig, replies, o);
}

