// The vcan integration cases (issue: SocketCAN pose intake). Runs where the
// kernel has SocketCAN and an interface vcan0 exists: inside the test VM
// (tests/can/run_vm.sh boots it once for all cases) or on a host with
// vcan. Linked statically so it needs nothing from the VM.
//
// usage: can_vm_cases all|CASE  (prints each check and "case X: PASS|FAIL")
// Peers are real programs: ig-send (the product's sender) and can-utils'
// cansend, started as child processes; the receiving side is the IG's own
// CanPoseSource, exactly as `ig serve --can` uses it.

#include <linux/can.h>
#include <linux/can/error.h>
#include <net/if.h>
#include <spawn.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "io/can/can_pose_source.h"
#include "io/filter/geodesy.h"
#include "io/net/udp_socket.h"
#include "io/path_interpolator.h"
#include "io/pose.h"
#include "io/scenario.h"

extern char** environ;

namespace {

using ig::io::can::CanFormat;
using ig::io::can::CanPoseSource;
using ig::io::wire::PoseMessage;

const std::string kIf = "vcan0";
const std::string kScenario = std::string(IG_SOURCE_DIR) + "/tests/can/can_path.json";
const std::string kSender = std::string(IG_BIN_DIR) + "/ig-send";

int g_failures = 0;

void check(bool ok, const std::string& what) {
  std::printf("  %s %s\n", ok ? "ok  " : "FAIL", what.c_str());
  if (!ok) ++g_failures;
}

std::string fmt(const char* f, double a, double b = 0) {
  char buf[256];
  std::snprintf(buf, sizeof(buf), f, a, b);
  return buf;
}

double now_s() { return ig::io::net::steady_now_s(); }

// A child process (argv[0] searched in PATH), reaped by wait().
struct Child {
  pid_t pid = -1;
  explicit Child(const std::vector<std::string>& argv) {
    std::vector<char*> a;
    for (const auto& s : argv) a.push_back(const_cast<char*>(s.c_str()));
    a.push_back(nullptr);
    if (posix_spawnp(&pid, a[0], nullptr, nullptr, a.data(), environ) != 0) pid = -1;
  }
  bool running() {
    if (pid < 0) return false;
    int st = 0;
    const pid_t r = waitpid(pid, &st, WNOHANG);
    if (r == 0) return true;
    status = WIFEXITED(st) ? WEXITSTATUS(st) : 128;
    pid = -1;
    return false;
  }
  int wait() {
    while (running()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    return status;
  }
  int status = -1;
};

int run(const std::string& cmd) {
  std::printf("  $ %s\n", cmd.c_str());
  std::fflush(stdout);
  return std::system(cmd.c_str());
}

struct Received {
  PoseMessage pose;
  double t_s;
  CanFormat format;
};

// Polls the source until `until()` is true or timeout_s passes.
std::vector<Received> receive(CanPoseSource& src, double timeout_s, const std::function<bool()>& until) {
  std::vector<Received> out;
  const double end = now_s() + timeout_s;
  while (now_s() < end) {
    src.poll([&](const PoseMessage& m, double t, CanFormat f) { out.push_back({m, t, f}); });
    if (until()) break;
    std::this_thread::sleep_for(std::chrono::microseconds(500));
  }
  src.poll([&](const PoseMessage& m, double t, CanFormat f) { out.push_back({m, t, f}); });
  return out;
}

// The scenario path as the sender sees it (local frame, MSL: no terrain
// needed) and the generated terrain's geographic grid (as ig-send's).
struct ScenarioPath {
  ig::io::Scenario scenario = ig::io::load_scenario(kScenario);
  ig::io::PathInterpolator path{scenario.path};
  std::optional<ig::io::geo::GeographicGrid> grid;
  ScenarioPath() {
    const auto& g = *scenario.terrain.generator;
    const auto m = ig::io::geo::metres_per_degree((*g.origin_lat_lon)[0]);
    grid = ig::io::geo::GeographicGrid::make(
        {(*g.origin_lat_lon)[1], g.spacing_m / m.east, 0.0, (*g.origin_lat_lon)[0], 0.0, g.spacing_m / m.north},
        g.spacing_m, g.spacing_m);
  }
  // Nearest path time to a local position within [t0, t1] (0.5 ms steps)
  // and its distance.
  std::pair<double, double> nearest(const glm::dvec3& p, double t0, double t1) const {
    double best_t = t0, best_d = 1e300;
    for (double t = std::max(0.0, t0); t <= std::min(t1, path.last_time_s()) + 1e-9; t += 0.0005) {
      const double d = glm::length(path.sample(t).position - p);
      if (d < best_d) best_d = d, best_t = t;
    }
    return {best_t, best_d};
  }
};

double angle_diff(double a, double b) {
  double d = std::fmod(a - b, 360.0);
  if (d > 180) d -= 360;
  if (d < -180) d += 360;
  return std::fabs(d);
}

CanPoseSource make_source() {
  ig::io::can::CanPoseSourceOptions o;
  o.ifname = kIf;
  o.retry_s = 0.05;
  return CanPoseSource(o);
}

// ---------------------------------------------------------------------------

int case_canaerospace_path() {
  std::printf("ig-send --can (CANaerospace, DOUBLE lat/lon) -> CanPoseSource, against the scenario path\n");
  ScenarioPath sp;
  auto src = make_source();
  check(src.poll([](auto&&...) {}) == 0 && src.socket().is_open(), "receiver open on " + kIf + " " + src.socket().last_error());
  Child sender({kSender, kScenario, "--can", kIf, "--rate", "100", "--quiet"});
  check(sender.pid > 0, "ig-send started");
  const auto got = receive(src, 40.0, [&] { return !sender.running(); });
  check(sender.status == 0, fmt("ig-send exit status %.0f", sender.status));
  const int sent = 3 * 100 + 1;
  check(int(got.size()) == sent, fmt("poses assembled %.0f of %.0f sent", double(got.size()), sent));
  const auto& c = src.canaerospace_stats();
  check(c.rejected() == 0, fmt("no frame rejected (%.0f)", double(c.rejected())));
  check(c.code_gaps == 0, fmt("no message-code gaps (%.0f)", double(c.code_gaps)));
  check(src.stale_cycles() == 0, fmt("no stale cycles (%.0f)", double(src.stale_cycles())));
  double worst_pos = 0, worst_att = 0;
  for (size_t k = 0; k < got.size(); ++k) {
    const auto& r = got[k];
    const glm::dvec3 local = sp.grid->to_local({r.pose.position.x, r.pose.position.y, r.pose.position.z});
    // Pose k is the path at k / rate when none is lost; search around it
    // (a search of the whole path per pose is slow under emulation).
    const auto [t, d] = sp.nearest(local, k * 0.01 - 0.05, k * 0.01 + 0.05);
    worst_pos = std::max(worst_pos, d);
    const auto hpr = ig::io::hpr_from_attitude(sp.path.sample(t).attitude);
    // The nearest point in position may be off in time by the 0.5 ms search
    // step; attitude rates here are below 60 deg/s, i.e. 0.03 deg.
    worst_att = std::max({worst_att, angle_diff(r.pose.heading_deg, hpr.heading_deg),
                          std::fabs(r.pose.pitch_deg - hpr.pitch_deg), angle_diff(r.pose.roll_deg, hpr.roll_deg)});
  }
  check(worst_pos < 0.05, fmt("every pose on the path: worst distance %.4f m (< 0.05)", worst_pos));
  check(worst_att < 0.1, fmt("attitude matches the path: worst %.4f deg (< 0.1)", worst_att));
  return 0;
}

int case_canfd_path() {
  std::printf("ig-send --can --can-fd (64-byte FD pose) -> CanPoseSource, against the scenario path\n");
  ScenarioPath sp;
  auto src = make_source();
  src.poll([](auto&&...) {});
  Child sender({kSender, kScenario, "--can", kIf, "--can-fd", "--rate", "100", "--quiet"});
  const auto got = receive(src, 40.0, [&] { return !sender.running(); });
  check(sender.status == 0, fmt("ig-send exit status %.0f", sender.status));
  check(got.size() == 301, fmt("FD poses received %.0f of %.0f", double(got.size()), 301));
  check(src.fd_stats().rejects.empty(), "no FD frame rejected");
  check(src.socket().stats().fd_frames == got.size(), "every frame arrived as CAN FD");
  double worst_pos = 0, worst_att = 0;
  bool in_order = true;
  std::uint32_t prev = 0;
  for (size_t k = 0; k < got.size(); ++k) {
    const auto& m = got[k].pose;
    if (k > 0 && m.sequence != prev + 1) in_order = false;
    prev = m.sequence;
    const auto ref = sp.path.sample(m.sequence * 0.01);  // pose i is the path at i / rate
    worst_pos = std::max(worst_pos, glm::length(ref.position - m.position));
    const auto hpr = ig::io::hpr_from_attitude(ref.attitude);
    worst_att = std::max({worst_att, angle_diff(m.heading_deg, hpr.heading_deg), std::fabs(m.pitch_deg - hpr.pitch_deg),
                          angle_diff(m.roll_deg, hpr.roll_deg)});
  }
  check(in_order && !got.empty(), "sequence numbers consecutive");
  check(worst_pos < 0.01, fmt("position = path at sequence/rate: worst %.5f m (< 0.01, f32 altitude)", worst_pos));
  check(worst_att < 1e-3, fmt("attitude = path: worst %.6f deg (< 1e-3, f32)", worst_att));
  return 0;
}

// CANaerospace frame for cansend: ID#DATA, 8 bytes, big-endian value.
std::string canas(int id, int node, int type, int code, std::uint32_t raw) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%03X#%02X%02X00%02X%08X", id, node, type, code, raw);
  return buf;
}
std::uint32_t f32_bits(float v) {
  std::uint32_t u;
  std::memcpy(&u, &v, 4);
  return u;
}
std::uint64_t f64_bits(double v) {
  std::uint64_t u;
  std::memcpy(&u, &v, 8);
  return u;
}

// A full pose as cansend frames: node 5, FLOAT attitude and altitude,
// DOUBLE latitude / longitude; `code` is the message code of every frame.
std::vector<std::string> pose_frames(int code, float pitch, float roll, float heading, float alt, double lat,
                                     double lon) {
  const std::uint64_t la = f64_bits(lat), lo = f64_bits(lon);
  return {canas(311, 5, 2, code, f32_bits(pitch)),         canas(312, 5, 2, code, f32_bits(roll)),
          canas(321, 5, 2, code, f32_bits(heading)),       canas(322, 5, 2, code, f32_bits(alt)),
          canas(1036, 5, 30, code, std::uint32_t(la >> 32)), canas(1036, 5, 31, code, std::uint32_t(la)),
          canas(1037, 5, 30, code, std::uint32_t(lo >> 32)), canas(1037, 5, 31, code, std::uint32_t(lo))};
}

int cansend(const std::string& frame) { return run("cansend " + kIf + " " + frame); }

int case_cansend_peer() {
  std::printf("can-utils cansend (a real peer) -> CanPoseSource: one pose, exact values\n");
  auto src = make_source();
  src.poll([](auto&&...) {});
  std::vector<Received> got;
  int rc = 0;
  for (const auto& f : pose_frames(7, 4.5f, -12.25f, 271.5f, 1234.5f, 46.512345678901, 7.923456789012)) rc |= cansend(f);
  check(rc == 0, "cansend exit status 0");
  got = receive(src, 2.0, [&] { return src.poses() > 0; });
  check(got.size() == 1, fmt("one pose assembled (%.0f)", double(got.size())));
  if (got.size() == 1) {
    const auto& m = got[0].pose;
    check(m.frame == PoseMessage::Frame::Geodetic, "geodetic pose");
    check(m.pitch_deg == 4.5 && m.roll_deg == -12.25 && m.heading_deg == 271.5, "attitude exactly as sent");
    check(m.position.z == 1234.5, "altitude (id 322) exactly as sent");
    check(m.position.x == 46.512345678901 && m.position.y == 7.923456789012,
          "DOUBLEH+DOUBLEL latitude / longitude exact to the last bit");
  }
  check(src.canaerospace_stats().accepted == 8 && src.canaerospace_stats().rejected() == 0, "8 frames accepted");
  return 0;
}

// Writes an error frame the way a CAN controller driver reports bus-off.
bool inject_bus_off_error_frame() {
  const int s = ::socket(PF_CAN, SOCK_RAW, CAN_RAW);
  if (s < 0) return false;
  ifreq ifr{};
  std::strncpy(ifr.ifr_name, kIf.c_str(), IFNAMSIZ - 1);
  ::ioctl(s, SIOCGIFINDEX, &ifr);
  sockaddr_can addr{};
  addr.can_family = AF_CAN;
  addr.can_ifindex = ifr.ifr_ifindex;
  bool ok = ::bind(s, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)) == 0;
  can_frame f{};
  f.can_id = CAN_ERR_FLAG | CAN_ERR_BUSOFF;
  f.len = CAN_ERR_DLC;
  ok = ok && ::write(s, &f, sizeof(f)) == sizeof(f);
  ::close(s);
  return ok;
}

int case_malformed() {
  std::printf("malformed and unknown frames (cansend + an injected error frame): counted and ignored\n");
  auto src = make_source();
  src.poll([](auto&&...) {});
  const std::uint64_t lat = f64_bits(46.5);
  int rc = 0;
  rc |= cansend("137#05020007408000");                                 // pitch, 7 bytes: wrong_dlc
  rc |= cansend("7FF#0502000740800000");                               // id 2047: unknown_id
  rc |= cansend(canas(1038, 5, 2, 1, f32_bits(100.f)));                // GPS height: not used -> unknown_id
  rc |= cansend(canas(311, 5, 30, 1, f32_bits(1.f)));                  // pitch as DOUBLEH: wrong_type
  rc |= cansend(canas(312, 5, 2, 1, 0x7FC00000u));                     // roll NaN: non_finite
  rc |= cansend(canas(1036, 5, 31, 9, std::uint32_t(lat)));            // DOUBLEL without DOUBLEH: orphan_low
  rc |= cansend("00000137#0502000740800000");                          // extended id: not_classic
  rc |= cansend("137#R");                                              // remote request: not_classic
  rc |= cansend("7E0##1" + std::string(128, '0'));                     // FD pose, bad magic
  check(rc == 0, "cansend exit status 0 for every frame");
  check(inject_bus_off_error_frame(), "error frame (bus-off) written");
  receive(src, 1.0, [&] { return src.socket().stats().error_frames > 0 && src.canaerospace_stats().frames >= 8; });
  const auto& c = src.canaerospace_stats();
  const auto& a = src.assembler_stats();
  check(c.wrong_dlc == 1, fmt("wrong_dlc = %.0f (1)", double(c.wrong_dlc)));
  check(c.unknown_id == 2, fmt("unknown_id = %.0f (2)", double(c.unknown_id)));
  check(c.wrong_type == 1, fmt("wrong_type = %.0f (1)", double(c.wrong_type)));
  check(c.non_finite == 1, fmt("non_finite = %.0f (1)", double(c.non_finite)));
  check(c.not_classic == 2, fmt("not_classic = %.0f (2: extended id, RTR)", double(c.not_classic)));
  check(a.orphan_low == 1, fmt("orphan DOUBLEL = %.0f (1)", double(a.orphan_low)));
  check(src.fd_stats().frames == 1 && src.fd_stats().accepted == 0, "FD frame with bad magic rejected");
  check(src.socket().stats().error_frames == 1, fmt("error frames = %.0f (1)", double(src.socket().stats().error_frames)));
  check(src.socket().stats().bus_off == 1, fmt("bus-off = %.0f (1)", double(src.socket().stats().bus_off)));
  check(src.poses() == 0, "no pose from any of them");
  // Nothing lost: a good pose right after is used.
  int rc2 = 0;
  for (const auto& f : pose_frames(20, 1.f, 2.f, 3.f, 500.f, 46.5, 7.9)) rc2 |= cansend(f);
  const auto got = receive(src, 2.0, [&] { return src.poses() > 0; });
  check(rc2 == 0 && got.size() == 1 && got[0].pose.heading_deg == 3.0, "the next good pose is assembled");
  return 0;
}

int case_link_flap() {
  std::printf("interface down/up and removed/re-created mid-stream: the source says why and recovers\n");
  auto src = make_source();
  src.poll([](auto&&...) {});
  // Long enough to outlast the flaps: every `ip` run costs ~0.5 s emulated.
  Child sender({kSender, kScenario, "--can", kIf, "--rate", "100", "--duration", "6", "--quiet"});
  check(sender.pid > 0, "ig-send started");
  std::vector<Received> got;
  std::vector<std::string> errors;
  std::uint64_t seen_state = src.socket().state_changes();
  auto pump = [&](double seconds) {
    const double end = now_s() + seconds;
    while (now_s() < end) {
      src.poll([&](const PoseMessage& m, double t, CanFormat f) { got.push_back({m, t, f}); });
      if (src.socket().state_changes() != seen_state) {
        seen_state = src.socket().state_changes();
        const std::string e = src.socket().last_error();
        std::printf("  source: %s\n", e.empty() ? "receiving" : e.c_str());
        if (!e.empty()) errors.push_back(e);
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  };
  // ig-send takes seconds to start under emulation: wait for its stream.
  for (double end = now_s() + 40.0; got.empty() && now_s() < end;) pump(0.05);
  pump(0.5);
  const size_t before_down = got.size();
  check(before_down > 30, fmt("poses before the link goes down: %.0f", double(before_down)));
  run("ip link set " + kIf + " down");
  pump(0.4);
  const size_t while_down = got.size() - before_down;
  run("ip link set " + kIf + " up");
  pump(0.5);
  const size_t after_up = got.size();
  check(after_up > before_down + while_down + 20, fmt("poses again after up: %.0f", double(after_up - before_down - while_down)));
  run("ip link del " + kIf);
  pump(0.3);
  run("ip link add dev " + kIf + " type vcan && ip link set " + kIf + " mtu 72 up");
  const size_t before_recreate = got.size();
  pump(0.6);
  check(got.size() > before_recreate + 20,
        fmt("poses again after the interface was re-created: %.0f", double(got.size() - before_recreate)));
  sender.wait();
  pump(0.1);
  check(sender.status == 0, fmt("ig-send survived the flaps (exit %.0f)", sender.status));
  bool said_down = false, said_removed = false;
  for (const auto& e : errors) {
    said_down |= e.find("down") != std::string::npos;
    said_removed |= e.find("removed") != std::string::npos || e.find("no such interface") != std::string::npos;
  }
  check(said_down, "said the interface went down");
  check(said_removed, "said the interface was removed");
  check(src.socket().is_open() && src.socket().last_error().empty(), "open and healthy at the end");
  check(src.socket().stats().opens >= 3, fmt("reopened: %.0f opens", double(src.socket().stats().opens)));
  return 0;
}

}  // namespace

// Benchmark, not a test (not in "all"): ig-send streams CANaerospace poses
// at 1 kHz (11 frames each, 11 k frames/s) through the VM's kernel; prints
// the pose rate the source sustains and what it counted. Emulated CPU: the
// figure is a lower bound for real hardware.
int bench_1khz() {
  std::printf("1 kHz CANaerospace stream (ig-send --rate 1000, 11 frames per pose) through vcan0\n");
  auto src = make_source();
  src.poll([](auto&&...) {});
  Child sender({kSender, kScenario, "--can", kIf, "--rate", "1000", "--duration", "3", "--quiet"});
  double first = -1, last = -1;
  std::uint64_t n = 0;
  const double end = now_s() + 60.0;
  while (now_s() < end && sender.running()) {
    src.poll([&](const PoseMessage&, double t, CanFormat) {
      if (first < 0) first = t;
      last = t;
      ++n;
    });
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  src.poll([&](const PoseMessage&, double t, CanFormat) { last = t, ++n; });
  const auto& st = src.socket().stats();
  std::printf("  poses %llu of 3001 sent, %.1f poses/s over %.2f s; frames %llu, kernel drops %llu, code gaps %llu, "
              "stale cycles %llu\n",
              (unsigned long long)n, n > 1 ? (n - 1) / (last - first) : 0.0, last - first,
              (unsigned long long)st.frames, (unsigned long long)st.kernel_drops,
              (unsigned long long)src.canaerospace_stats().code_gaps, (unsigned long long)src.stale_cycles());
  return 0;
}

int run_case(const std::string& name, int (*fn)()) {
  g_failures = 0;
  std::printf("case %s\n", name.c_str());
  const double t0 = now_s();
  try {
    fn();
  } catch (const std::exception& e) {
    check(false, std::string("exception: ") + e.what());
  }
  std::printf("case %s: %s (%d failed checks, %.1f s)\n", name.c_str(), g_failures ? "FAIL" : "PASS", g_failures,
              now_s() - t0);
  std::fflush(stdout);
  return g_failures ? 1 : 0;
}

int main(int argc, char** argv) {
  // link_flap last: it deletes and re-creates the interface.
  const std::vector<std::pair<std::string, int (*)()>> cases = {
      {"canaerospace_path", case_canaerospace_path}, {"canfd_path", case_canfd_path},
      {"cansend_peer", case_cansend_peer},           {"malformed", case_malformed},
      {"link_flap", case_link_flap},
  };
  const std::string want = argc == 2 ? argv[1] : "";
  if (want == "bench_1khz") return run_case(want, bench_1khz);
  int failed = 0, ran = 0;
  for (const auto& [name, fn] : cases)
    if (want == "all" || want == name) failed += run_case(name, fn), ++ran;
  if (ran == 0) {
    std::fprintf(stderr, "usage: can_vm_cases all|CASE  (");
    for (const auto& c : cases) std::fprintf(stderr, " %s", c.first.c_str());
    std::fprintf(stderr, " )\n");
    return 2;
  }
  return failed ? 1 : 0;
}
