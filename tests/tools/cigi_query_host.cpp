// A CIGI 3.3 test host for ig serve's host services (tests/cli/host_services.cmake).
// Synchronous operation: waits for the IG's first Start Of Frame, then sends
// one datagram per frame (IG Control, the ownship, HAT/HOT and LOS requests of
// every type, alternately big- and little-endian) and waits for the Start Of
// Frame echoing that host frame, whose datagram carries the answers. Checks
// them against the DEM read here (Heightfield::sample_surface, not the IG's
// query code): HOT within 0.01 m, LOS hit points on the surface and on the
// line, vertical LOS ranges equal to the HAT, clear lines visible, points
// outside the terrain invalid, a periodic request answered every 2nd frame
// until cancelled. Prints PASS or FAIL lines.
//
//   cigi_query_host DEM_FILE IG_ADDR:PORT LISTEN_ADDR:PORT FRAMES [--native IG_UDP_ADDR:PORT]
//   cigi_query_host DEM_FILE IG_ADDR:PORT LISTEN_ADDR:PORT FRAMES --bench HOT LOS [SPREAD_M]
//   cigi_query_host DEM_FILE IG_ADDR:PORT LISTEN_ADDR:PORT FRAMES --flood PER_FRAME BUDGET
//   cigi_query_host TERRAIN IG_ADDR:PORT LISTEN_ADDR:PORT --soak HOT LOS --duration S
//                   [--rate HZ] [--spread M] [--circle LAT,LON,RADIUS_M | --radius M] [--speed MPS] [--agl M]
//
// --native: each frame also sends native height / line-of-sight queries
// ("IGQR") to the IG's native port from its own socket, and checks the
// answers that came back before the frame's Start Of Frame.
//
// --bench: no checks; HOT HAT/HOT and LOS requests (half segments, half
// vectors, 5-20 km; tools/load/cigi_request_mix.h, the load of the
// in-process bench_host_services) every frame at most 60 frames a second, and the time
// from sending a frame to receiving its answers (docs/results.md). HAT/HOT
// points are spread over the whole DEM, or within SPREAD_M of the ownship.
//
// --flood: against an IG in its own time (not synchronous): for FRAMES of
// the IG's Start Of Frames, sends PER_FRAME HOT requests (in datagrams of
// 1000) after each, more than the IG's per-frame BUDGET, then reads on until
// every request is answered. Checks: each answer once, no datagram with
// more than BUDGET HAT/HOT answers, the IG's frames went on (PASS / FAIL).
// --soak: tests/tools/cigi_soak_host.cpp.
//
// Long because it is a whole CIGI host: every request type in both byte
// orders, the synchronous frame loop, the checks and the benchmark mode.
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
#include "cigi_soak_host.h"
#include "session/scene_setup.h"
#include "terrain/dem_loader.h"
#include "terrain/earth_curvature.h"

namespace {

using namespace ig::io::wire;
using glm::dvec3;

int failures = 0;
void fail(const std::string& what) {
  if (++failures <= 20) std::printf("FAIL %s\n", what.c_str());
}

struct Expect {
  enum Kind { Hot, HotOutside, HatOwnship, SegmentHit, SegmentClear, VectorDown, VectorSlant } kind;
  dvec3 local_from{0.0}, local_to{0.0};  // terrain-local metres (flat DEM frame)
  double alt = 0.0;
  bool extended = false;
  HatHotType type = HatHotType::Hat;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 5 && std::string(argv[4]) == "--soak") return soak_main(argc, argv);
  const bool bench = (argc == 8 || argc == 9) && std::string(argv[5]) == "--bench";
  const bool native = argc == 7 && std::string(argv[5]) == "--native";
  const bool flood = argc == 8 && std::string(argv[5]) == "--flood";
  if (argc != 5 && !bench && !native && !flood) {
    std::fprintf(stderr, "usage: cigi_query_host DEM_FILE IG_ADDR:PORT LISTEN_ADDR:PORT FRAMES [--bench HOT LOS [SPREAD_M]]\n");
    return 2;
  }
  const ig::terrain::Heightfield hf = ig::terrain::load_dem(argv[1]);
  const auto grid = ig::io::geo::GeographicGrid::make(hf.georef->grid_to_crs, hf.spacing_x_m, hf.spacing_y_m);
  ig::io::net::UdpSender to_ig(argv[2]);
  ig::io::net::UdpReceiver replies(argv[3]);
  const int frames = std::stoi(argv[4]);
  // Native queries go out from this socket; answers come back to it.
  std::unique_ptr<ig::io::net::UdpReceiver> native_socket;
  sockaddr_in native_ig{};
  if (native) {
    native_socket = std::make_unique<ig::io::net::UdpReceiver>("127.0.0.1:0");
    native_ig = ig::io::net::parse_endpoint(argv[6]);
  }
  std::size_t native_checked = 0;
  double native_worst = 0.0;
  const double R = ig::terrain::kEarthRadiusM;  // the Sierra scenario draws with curvature ("auto")
  auto local = [&](const dvec3& g) { return grid->to_local({g.x, g.y, g.z}); };
  auto geodetic = [&](const dvec3& l) {
    const auto g = grid->from_local(l);
    return dvec3(g.lat_deg, g.lon_deg, g.height_m);
  };

  // Block until a datagram arrives (the IG repeats its first Start Of Frame
  // while it waits for the host; ctest's own timeout bounds a dead IG).
  auto next_datagram = [&]() {
    std::vector<std::uint8_t> got;
    while (got.empty()) {
      replies.wait_readable(1.0);
      replies.poll([&](std::span<const std::uint8_t> d, double, const sockaddr_in&) { got.assign(d.begin(), d.end()); },
                   1);
    }
    return got;
  };
  while (!decode_cigi_start_of_frame(next_datagram()).sof) {
  }

  std::mt19937_64 rng(15);
  std::uniform_real_distribution<double> ux(0.05 * hf.extent_x_m(), 0.95 * hf.extent_x_m()),
      uy(0.05 * hf.extent_y_m(), 0.95 * hf.extent_y_m()), uaz(-180, 180);
  if (flood) {
    const int per_frame = std::stoi(argv[6]);
    const std::size_t budget = std::stoul(argv[7]);
    std::vector<int> answered(65536, 0);
    std::size_t sent = 0, got = 0, max_in_datagram = 0, sofs = 0, sofs_with_answers = 0;
    std::uint32_t first_ig_frame = 0, last_ig_frame = 0;
    auto read_frame = [&] {  // one IG frame's datagram: count its answers
      for (;;) {
        const auto dg = next_datagram();
        const auto sof = decode_cigi_start_of_frame(dg);
        if (!sof.sof) continue;
        if (sofs++ == 0) first_ig_frame = sof.sof->ig_frame;
        last_ig_frame = sof.sof->ig_frame;
        std::size_t n = 0;
        if (const auto r = decode_cigi_responses(dg))
          for (const auto& a : *r)
            if (const auto* h = std::get_if<HatHotResponse>(&a)) {
              ++answered[h->id];
              ++n;
            }
        got += n;
        sofs_with_answers += n > 0;
        max_in_datagram = std::max(max_in_datagram, n);
        return;
      }
    };
    const dvec3 own_at(0.5 * hf.extent_x_m(), 0.4 * hf.extent_y_m(), 4000.0);
    for (int k = 1; k <= frames; ++k) {
      for (int left = per_frame; left > 0; left -= 1000) {
        PoseMessage ownship;
        ownship.frame = PoseMessage::Frame::Geodetic;
        ownship.position = geodetic(own_at);
        std::vector<std::uint8_t> d = encode_cigi_host_datagram(std::uint32_t(k), kCigiModeOperate, ownship, false);
        for (int n = 0; n < std::min(left, 1000); ++n) {
          HatHotRequest r;
          r.id = std::uint16_t(sent++);
          r.type = HatHotType::Hot;
          r.point = geodetic(dvec3(ux(rng), uy(rng), 3000.0));
          const auto packet = encode_cigi_hat_hot_request(r, false);
          d.insert(d.end(), packet.begin(), packet.end());
        }
        to_ig.send(d);
      }
      read_frame();  // the IG's next frame paces the host, no clock involved
    }
    // Drain: the IG answers the backlog a budget per frame.
    std::size_t idle = 0;
    while (got < sent && idle < 20) {
      const std::size_t before = got;
      read_frame();
      idle = got == before ? idle + 1 : 0;
    }
    std::size_t duplicates = 0, missing = 0;
    for (std::size_t id = 0; id < sent; ++id) {
      missing += answered[id] == 0;
      duplicates += answered[id] > 1;
    }
    std::printf("flood: %zu HOT requests sent over %d IG frames (%d a frame), %zu answered, %zu missing, %zu twice; "
                "at most %zu answers in one IG datagram (budget %zu); %zu IG frames seen (IG frames %u..%u), %zu with "
                "answers\n",
                sent, frames, per_frame, got, missing, duplicates, max_in_datagram, budget, sofs, first_ig_frame,
                last_ig_frame, sofs_with_answers);
    const bool ok = missing == 0 && duplicates == 0 && max_in_datagram <= budget &&
                    sofs_with_answers >= sent / budget && last_ig_frame > first_ig_frame;
    std::printf("%s flood\n", ok ? "PASS" : "FAIL");
    return ok ? 0 : 1;
  }
  if (bench) {
    const int n_hot = std::stoi(argv[6]), n_los = std::stoi(argv[7]);
    const double spread = argc == 9 ? std::stod(argv[8]) : 0.0;
    const ig::load::RequestLoad load{n_hot, n_los, spread};
    ig::load::CigiRequestMix mix(hf);  // the load of bench_host_services
    PoseMessage ownship;
    ownship.frame = PoseMessage::Frame::Geodetic;
    ownship.position = mix.geodetic(mix.ownship_at());
    std::vector<double> latency_ms;
    auto tick = std::chrono::steady_clock::now();
    std::size_t answers = 0;
    for (int k = 1; k <= frames; ++k) {
      const std::vector<std::uint8_t> d = mix.datagram(std::uint32_t(k), load, ownship);
      const auto sent = std::chrono::steady_clock::now();
      to_ig.send(d);
      for (;;) {
        const auto dg = next_datagram();
        const auto sof = decode_cigi_start_of_frame(dg);
        if (!sof.sof || sof.sof->last_host_frame != std::uint32_t(k)) continue;
        latency_ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - sent).count());
        if (const auto r = decode_cigi_responses(dg)) answers += r->size();
        break;
      }
      tick += std::chrono::microseconds(16667);  // a 60 Hz host at most
      std::this_thread::sleep_until(tick);
    }
    std::sort(latency_ms.begin(), latency_ms.end());
    auto pct = [&](double q) { return latency_ms[std::min(latency_ms.size() - 1, std::size_t(q * latency_ms.size()))]; };
    std::printf("bench: %d frames, %d HAT/HOT (%s) + %d LOS requests a frame, %zu answers (%.1f a frame)\n", frames,
                n_hot, spread > 0 ? ("within " + std::to_string(int(spread)) + " m of the ownship").c_str() : "whole DEM",
                n_los, answers, double(answers) / frames);
    std::printf("request -> response latency (send to the answers' datagram received): median %.2f ms, p95 %.2f ms, "
                "max %.2f ms\n",
                pct(0.5), pct(0.95), latency_ms.back());
    return 0;
  }
  ig::io::Pose own;  // the ownship the IG renders (synchronous: as sent)
  own.position = {0.5 * hf.extent_x_m(), 0.4 * hf.extent_y_m(), 0.0};
  own.position.z = hf.sample_surface(own.position.x, own.position.y) + 1500.0;
  const ig::io::Hpr own_hpr{250.0, 5.0, -10.0};  // exact in f32, as the wire carries them
  own.attitude = ig::io::attitude_from_hpr(own_hpr);

  std::size_t hot_checked = 0, los_hits = 0, los_clear = 0, invalid_ok = 0;
  double hot_worst = 0.0, los_surface_worst = 0.0, los_line_worst = 0.0;
  std::set<int> periodic_frames;
  std::set<bool> orders_seen;
  for (int k = 1; k <= frames; ++k) {
    const bool swap = k % 2 == 1;
    orders_seen.insert(swap);
    PoseMessage ownship;
    ownship.frame = PoseMessage::Frame::Geodetic;
    ownship.position = geodetic(own.position);
    ownship.heading_deg = own_hpr.heading_deg;
    ownship.pitch_deg = own_hpr.pitch_deg;
    ownship.roll_deg = own_hpr.roll_deg;
    std::vector<std::uint8_t> d = encode_cigi_host_datagram(std::uint32_t(k), kCigiModeOperate, ownship, swap);
    std::map<std::uint16_t, Expect> expect;
    auto add = [&](const auto& packet) { d.insert(d.end(), packet.begin(), packet.end()); };
    std::uint16_t id = 0;
    for (int n = 0; n < 60; ++n, ++id) {  // HOT / HAT / extended at random points
      const dvec3 l(ux(rng), uy(rng), 0.0);
      HatHotRequest r;
      r.id = id;
      r.type = HatHotType(n % 3);
      r.point = geodetic(dvec3(l.x, l.y, 3000.0 + n));
      add(encode_cigi_hat_hot_request(r, swap));
      Expect e{Expect::Hot, local(r.point)};
      e.alt = r.point.z;
      e.type = r.type;
      expect[id] = e;
    }
    {  // outside the DEM: valid clear
      HatHotRequest r;
      r.id = id;
      r.type = HatHotType::Extended;
      r.point = geodetic(dvec3(-5000.0, 1000.0, 100.0));
      add(encode_cigi_hat_hot_request(r, swap));
      expect[id++] = Expect{Expect::HotOutside};
    }
    {  // the ownship's own HAT, entity-relative
      HatHotRequest r;
      r.id = id;
      r.coords = CigiCoords::Entity;
      add(encode_cigi_hat_hot_request(r, swap));
      expect[id++] = Expect{Expect::HatOwnship, own.position};
    }
    for (int n = 0; n < 6; ++n, ++id) {  // segments: down through the terrain, or high above it
      const dvec3 a(ux(rng), uy(rng), 0.0), b(ux(rng), uy(rng), 0.0);
      const bool clear = n % 2 == 1;
      const dvec3 from(a.x, a.y, clear ? 9000.0 : hf.sample_surface(a.x, a.y) + 2000.0);
      const double db = glm::length(dvec3(b - a));
      const dvec3 to(b.x, b.y, clear ? 9000.0 + ig::terrain::curvature_drop(db, R) : hf.sample_surface(b.x, b.y) - 50.0);
      LosSegmentRequest r;
      r.id = id;
      r.extended = n % 3 != 2;
      r.source = geodetic(from);
      r.destination = geodetic(to);
      add(encode_cigi_los_segment_request(r, swap));
      Expect e{clear ? Expect::SegmentClear : Expect::SegmentHit, local(r.source), local(r.destination)};
      e.extended = r.extended;
      expect[id] = e;
    }
    for (int n = 0; n < 6; ++n, ++id) {  // vectors: straight down (= HAT) or slanting down
      const dvec3 a(ux(rng), uy(rng), 0.0);
      LosVectorRequest r;
      r.id = id;
      r.extended = n % 2 == 0;
      r.source = geodetic(dvec3(a.x, a.y, hf.sample_surface(a.x, a.y) + 700.0));
      const bool down = n < 3;
      r.azimuth_deg = float(uaz(rng));
      r.elevation_deg = down ? -90.0f : -15.0f;
      r.max_range_m = 30000.0f;
      add(encode_cigi_los_vector_request(r, swap));
      Expect e{down ? Expect::VectorDown : Expect::VectorSlant, local(r.source)};
      e.extended = r.extended;
      if (!down) {
        const double az = r.azimuth_deg * M_PI / 180, el = r.elevation_deg * M_PI / 180;
        e.local_to = e.local_from + dvec3(std::cos(el) * std::sin(az), std::cos(el) * std::cos(az), std::sin(el));
      }
      expect[id] = e;
    }
    // Frame 1 also sets the view: 20 deg left, 3 deg down, 50 deg vertical
    // FOV (the IG's summary.json view_control counts 2 applied).
    if (k == 1) {
      CigiViewControl vc;
      vc.yaw_deg = -20.0f;
      vc.pitch_deg = -3.0f;
      CigiViewDefinition vd;
      vd.top_deg = 25.0f;
      vd.bottom_deg = -25.0f;
      add(encode_cigi_view_control(vc, swap));
      add(encode_cigi_view_definition(vd, swap));
    }
    // A periodic HOT (every 2nd frame) from frame 1, cancelled in frame 7.
    if (k == 1 || k == 7) {
      HatHotRequest r;
      r.id = 900;
      r.type = HatHotType::Hot;
      r.update_period = k == 1 ? 2 : 0;
      r.point = geodetic(own.position);
      add(encode_cigi_hat_hot_request(r, swap));
    }
    // Native queries first: the IG reads its other sources after the frame's
    // CIGI datagram and answers them at once, before the Start Of Frame.
    std::map<std::uint32_t, dvec3> native_expect;  // id -> local point (height) or source (vertical LOS)
    if (native) {
      for (std::uint32_t n = 0; n < 20; ++n) {
        NativeQuery q;
        q.id = std::uint32_t(k) * 100 + n;
        const dvec3 l(ux(rng), uy(rng), 0.0);
        if (n % 4 == 3) {  // straight down in local metres: range = height above the surface
          q.kind = NativeQueryKind::LosVector;
          q.a = dvec3(l.x, l.y, hf.sample_surface(l.x, l.y) + 321.0);
          q.b = dvec3(0, 0, -1);
          q.max_range_m = 1e4;
          native_expect[q.id] = q.a;
        } else {
          q.kind = NativeQueryKind::Height;
          q.geodetic = true;
          q.a = geodetic(dvec3(l.x, l.y, 2500.0));
          native_expect[q.id] = local(q.a);
        }
        native_socket->send_to(encode_native_query(q), native_ig);
      }
    }
    to_ig.send(d);

    // This frame's answers: the datagram whose Start Of Frame echoes host frame k.
    std::vector<CigiResponse> got;
    for (;;) {
      const auto dg = next_datagram();
      const auto sof = decode_cigi_start_of_frame(dg);
      if (!sof.sof || sof.sof->last_host_frame != std::uint32_t(k)) continue;
      const auto r = decode_cigi_responses(dg);
      if (!r) fail("frame " + std::to_string(k) + ": undecodable responses");
      if (r) got = *r;
      break;
    }
    if (native) {
      std::size_t got_native = 0;
      native_socket->poll(
          [&](std::span<const std::uint8_t> dg, double, const sockaddr_in&) {
            const auto a = decode_native_answer(dg);
            if (!a || !native_expect.count(a->id) || !a->valid) {
              fail("native answer undecodable, unknown or invalid");
              return;
            }
            ++got_native;
            const dvec3 p = native_expect.at(a->id);
            const double hot = hf.sample_surface(p.x, p.y);
            const double err = a->kind == NativeQueryKind::Height ? std::abs(a->hot_or_range_m - hot)
                                                                  : std::abs(a->hot_or_range_m - (p.z - hot));
            native_worst = std::max(native_worst, err);
            ++native_checked;
          },
          1000);
      if (got_native != native_expect.size())
        fail("frame " + std::to_string(k) + ": " + std::to_string(got_native) + " of " +
             std::to_string(native_expect.size()) + " native answers before the Start Of Frame");
    }
    std::set<std::uint16_t> answered;
    for (const CigiResponse& resp : got) {
      if (const auto* h = std::get_if<HatHotResponse>(&resp)) {
        if (h->host_frame != std::uint32_t(k & 0xF)) fail("host frame LSN");
        if (h->id == 900) {
          periodic_frames.insert(k);
          if (!h->valid || std::abs(h->hot_m - hf.sample_surface(own.position.x, own.position.y)) > 0.01)
            fail("periodic HOT");
          continue;
        }
        answered.insert(h->id);
        const Expect& e = expect.at(h->id);
        if (e.kind == Expect::HotOutside) {
          if (h->valid) fail("HOT outside the terrain marked valid");
          else ++invalid_ok;
          continue;
        }
        const double hot = hf.sample_surface(e.local_from.x, e.local_from.y);
        if (!h->valid) {
          fail("HOT invalid inside the terrain");
          continue;
        }
        if (e.kind == Expect::HatOwnship) {
          if (std::abs(h->hat_m - (own.position.z - hot)) > 0.01) fail("ownship HAT");
          continue;
        }
        if (h->extended != (e.type == HatHotType::Extended)) fail("HAT/HOT response kind");
        double err = 0.0;
        if (h->extended) err = std::max(std::abs(h->hot_m - hot), std::abs(h->hat_m - (e.alt - hot)));
        else if (h->type == HatHotType::Hot) err = std::abs(h->hot_m - hot);
        else err = std::abs(h->hat_m - (e.alt - hot));
        if (!h->extended && h->type != e.type) fail("HAT/HOT response type");
        hot_worst = std::max(hot_worst, err);
        ++hot_checked;
        continue;
      }
      const LosResponse& l = std::get<LosResponse>(resp);
      answered.insert(l.id);
      const Expect& e = expect.at(l.id);
      if (l.host_frame != std::uint32_t(k & 0xF)) fail("LOS host frame LSN");
      if (!l.valid) {
        fail("LOS invalid from inside the terrain");
        continue;
      }
      if (l.extended != e.extended) fail("LOS response kind");
      if (e.kind == Expect::SegmentClear) {
        if (!l.visible || l.range_valid) fail("clear segment reported blocked");
        else ++los_clear;
        continue;
      }
      if (l.visible) {
        fail("LOS through the terrain reported visible, id " + std::to_string(l.id));
        continue;
      }
      ++los_hits;
      if (e.kind == Expect::VectorDown &&
          std::abs(l.range_m - (e.local_from.z - hf.sample_surface(e.local_from.x, e.local_from.y))) > 0.01)
        fail("vertical LOS range != HAT");
      if (!l.extended) continue;
      // The hit: on the DEM surface, and (in the source's tangent frame, the
      // terrain lowered by the curvature drop) on the line at the given range.
      const dvec3 p = local(l.point);
      los_surface_worst = std::max(los_surface_worst, std::abs(p.z - hf.sample_surface(p.x, p.y)));
      auto tangent = [&](const dvec3& q) {
        return dvec3(q.x, q.y, q.z - ig::terrain::curvature_drop(glm::length(glm::dvec2(q - e.local_from)), R));
      };
      const dvec3 from = e.local_from, hit = tangent(p);
      const dvec3 dir = e.kind == Expect::VectorDown ? dvec3(0, 0, -1)
                        : e.kind == Expect::VectorSlant ? glm::normalize(e.local_to - from)
                                                        : glm::normalize(tangent(e.local_to) - from);
      const double off_line = glm::length(glm::cross(hit - from, dir));
      los_line_worst = std::max({los_line_worst, off_line, std::abs(glm::length(hit - from) - l.range_m)});
    }
    for (const auto& [i, e] : expect)
      if (!answered.count(i)) fail("frame " + std::to_string(k) + ": no answer to request " + std::to_string(i));
  }
  std::printf("HOT/HAT answers checked: %zu, max error %.3g m (valid clear outside: %zu)\n", hot_checked, hot_worst,
              invalid_ok);
  std::printf("LOS: %zu hits (on the surface within %.3g m, on the line within %.3g m), %zu clear\n", los_hits,
              los_surface_worst, los_line_worst, los_clear);
  std::string pf;
  for (int f : periodic_frames) pf += std::to_string(f) + " ";
  std::printf("periodic request answered in frames: %s\n", pf.c_str());
  std::printf("byte orders sent: %zu\n", orders_seen.size());
  if (native) {
    std::printf("native queries answered: %zu, max error %.3g m\n", native_checked, native_worst);
    if (native_checked == 0 || native_worst >= 0.01) fail("native answers");
  }
  if (hot_worst >= 0.01) fail("HOT error");
  if (los_surface_worst >= 0.01 || los_line_worst >= 0.002) fail("LOS hit geometry");
  if (frames >= 9 && periodic_frames != std::set<int>{1, 3, 5, 7}) fail("periodic answers not every 2nd frame until cancelled");
  if (los_hits == 0 || los_clear == 0 || hot_checked == 0) fail("nothing checked");
  std::printf(failures ? "FAIL host services\n" : "PASS host services\n");
  return failures ? 1 : 0;
}
