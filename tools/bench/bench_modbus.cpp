// Benchmark: Modbus TCP request round-trip time against a running ig serve,
// and the frame-time effect of 16 clients polling its status at 100 Hz
// (frame wall_ms from the IG's own frames.csv, phases without / with polling
// interleaved in one run). Also the libmodbus polling client of the cli tests.
//
//   bench_modbus                          start ig serve (beside this binary) and measure
//       [--size WxH] [--phase-s S] [--reads N]
//   bench_modbus --connect HOST:PORT --poll N [--rate HZ] [--seconds S]
//                                         N clients polling; exit 1 on any error
#if IG_WITH_MODBUS
#include <modbus/modbus.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "io/control/register_map.h"

namespace {
namespace ctl = ig::io::control;
using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

struct Endpoint {
  std::string host;
  int port = 0;
};

modbus_t* connect_client(const Endpoint& ep) {
  modbus_t* c = modbus_new_tcp(ep.host.c_str(), ep.port);
  modbus_set_response_timeout(c, 1, 0);
  if (modbus_connect(c) != 0) {
    modbus_free(c);
    return nullptr;
  }
  return c;
}

double pct(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, std::size_t(q * double(v.size())))];
}

std::uint32_t frame_counter(modbus_t* c) {
  std::uint16_t r[2] = {0, 0};
  if (modbus_read_input_registers(c, ctl::in::kFrameCounter, 2, r) != 2) return 0;
  return ctl::get_u32(r);
}

struct PollResult {
  long reads = 0, errors = 0, backwards = 0, connect_failures = 0;
  std::uint32_t first = 0, last = 0;
  std::vector<double> rtt_us;
};

// n clients, each reading the whole status block at `rate` Hz for `seconds`.
PollResult poll(const Endpoint& ep, int n, double rate, double seconds) {
  std::vector<PollResult> per(n);
  std::vector<std::thread> threads;
  const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / rate));
  for (int i = 0; i < n; ++i)
    threads.emplace_back([&, i] {
      PollResult& p = per[i];
      modbus_t* c = connect_client(ep);
      if (!c) {
        ++p.connect_failures;
        return;
      }
      const auto end = Clock::now() + std::chrono::duration<double>(seconds);
      auto next = Clock::now();
      std::uint32_t last = 0;
      while (Clock::now() < end) {
        std::uint16_t r[ctl::in::kCount];
        const auto t0 = Clock::now();
        if (modbus_read_input_registers(c, 0, ctl::in::kCount, r) != ctl::in::kCount) {
          ++p.errors;
        } else {
          p.rtt_us.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t0).count());
          ++p.reads;
          const std::uint32_t fc = ctl::get_u32(&r[ctl::in::kFrameCounter]);
          if (p.reads == 1) p.first = fc;
          if (fc < last) ++p.backwards;
          last = p.last = fc;
        }
        next += period;
        std::this_thread::sleep_until(next);
      }
      modbus_close(c);
      modbus_free(c);
    });
  for (auto& t : threads) t.join();
  PollResult all;
  all.first = UINT32_MAX;
  for (const auto& p : per) {
    all.reads += p.reads;
    all.errors += p.errors;
    all.backwards += p.backwards;
    all.connect_failures += p.connect_failures;
    all.first = std::min(all.first, p.first);
    all.last = std::max(all.last, p.last);
    all.rtt_us.insert(all.rtt_us.end(), p.rtt_us.begin(), p.rtt_us.end());
  }
  return all;
}

int poll_mode(const Endpoint& ep, int n, double rate, double seconds) {
  const PollResult r = poll(ep, n, rate, seconds);
  std::printf("%d clients x %.0f Hz for %.1f s: %ld reads, %ld errors, %ld connect failures, %ld frame counter "
              "steps backwards; frame counter %u -> %u; round trip median %.0f us, p99 %.0f us\n",
              n, rate, seconds, r.reads, r.errors, r.connect_failures, r.backwards, r.first, r.last,
              pct(r.rtt_us, 0.5), pct(r.rtt_us, 0.99));
  const bool ok = r.errors == 0 && r.connect_failures == 0 && r.backwards == 0 && r.last > r.first &&
                  r.reads >= long(0.7 * n * rate * seconds);
  std::printf(ok ? "polling ok\n" : "FAIL: polling\n");
  return ok ? 0 : 1;
}

// frames.csv: frame -> wall_ms.
std::vector<std::pair<long, double>> read_frames(const std::string& path) {
  std::ifstream f(path);
  std::string line;
  std::getline(f, line);
  int frame_col = -1, wall_col = -1, col = 0;
  std::stringstream hs(line);
  for (std::string h; std::getline(hs, h, ','); ++col) {
    if (h == "frame") frame_col = col;
    if (h == "wall_ms") wall_col = col;
  }
  std::vector<std::pair<long, double>> out;
  while (std::getline(f, line)) {
    std::stringstream ss(line);
    std::string cell;
    long fr = -1;
    double w = 0;
    for (int c = 0; std::getline(ss, cell, ','); ++c) {
      if (c == frame_col) fr = std::atol(cell.c_str());
      if (c == wall_col) w = std::atof(cell.c_str());
    }
    out.emplace_back(fr, w);
  }
  return out;
}

int bench_mode(const std::string& bin_dir, const std::string& size, double phase_s, int reads) {
  const Endpoint ep{"127.0.0.1", 47391};
  const std::string out = (std::filesystem::temp_directory_path() / ("bench_modbus_" + std::to_string(getpid()))).string();
  const std::string ig = bin_dir + "/ig";
  const std::string seconds = std::to_string(int(phase_s * 4 + 30));
  const pid_t pid = fork();
  if (pid == 0) {
    execl(ig.c_str(), "ig", "serve", "--headless", "--udp", "127.0.0.1:47390", "--modbus", "127.0.0.1:47391",
          "--seconds", seconds.c_str(), "--size", size.c_str(), "--out", out.c_str(), "--quiet", (char*)nullptr);
    std::perror("exec ig");
    _exit(127);
  }
  modbus_t* c = nullptr;
  for (int k = 0; k < 100 && !c; ++k) {
    std::this_thread::sleep_for(100ms);
    c = connect_client(ep);
  }
  if (!c) {
    std::fprintf(stderr, "bench_modbus: cannot reach ig serve's Modbus server\n");
    kill(pid, SIGTERM);
    waitpid(pid, nullptr, 0);
    return 1;
  }
  std::this_thread::sleep_for(2s);  // warm-up

  // Round trip: one client, sequential reads of the whole status block, while the IG renders.
  std::vector<double> rtt;
  std::uint16_t r[ctl::in::kCount];
  for (int i = 0; i < reads; ++i) {
    const auto t0 = Clock::now();
    if (modbus_read_input_registers(c, 0, ctl::in::kCount, r) == ctl::in::kCount)
      rtt.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t0).count());
  }
  std::vector<double> wrtt;  // a write (FC 16, the thresholds, same values back)
  std::uint16_t th[4];
  modbus_read_registers(c, ctl::hold::kA1, 4, th);
  for (int i = 0; i < reads / 4; ++i) {
    const auto t0 = Clock::now();
    if (modbus_write_registers(c, ctl::hold::kA1, 4, th) == 4)
      wrtt.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t0).count());
  }

  // Frame time: phases without / with 16 clients at 100 Hz, interleaved.
  struct Phase {
    bool polling;
    std::uint32_t from, to;
    PollResult poll;
  };
  std::vector<Phase> phases;
  for (int k = 0; k < 4; ++k) {
    const bool polling = k % 2 == 1;
    Phase p{polling, frame_counter(c), 0, {}};
    if (polling) p.poll = poll(ep, 16, 100.0, phase_s);
    else std::this_thread::sleep_for(std::chrono::duration<double>(phase_s));
    p.to = frame_counter(c);
    phases.push_back(std::move(p));
  }
  modbus_close(c);
  modbus_free(c);
  kill(pid, SIGTERM);
  int status = 0;
  waitpid(pid, &status, 0);

  const auto frames = read_frames(out + "/frames.csv");
  std::vector<double> without, with;
  long without_n = 0, with_n = 0;
  std::vector<double> poll_rtt;
  long poll_reads = 0, poll_errors = 0;
  for (const auto& p : phases) {
    // frames.csv "frame" is 0-based; the counter counts frames rendered.
    for (const auto& [fr, w] : frames)
      if (fr >= long(p.from) + 5 && fr < long(p.to)) (p.polling ? with : without).push_back(w);
    (p.polling ? with_n : without_n) += p.to - p.from;
    if (p.polling) {
      poll_rtt.insert(poll_rtt.end(), p.poll.rtt_us.begin(), p.poll.rtt_us.end());
      poll_reads += p.poll.reads;
      poll_errors += p.poll.errors + p.poll.connect_failures;
    }
  }
  std::printf("Modbus TCP against ig serve --headless --size %s (loopback, 2 phases of %.0f s each way)\n",
              size.c_str(), phase_s);
  std::printf("  read 30 input registers (FC 04), 1 client, %zu requests: round trip median %.0f us, p99 %.0f us\n",
              rtt.size(), pct(rtt, 0.5), pct(rtt, 0.99));
  std::printf("  write 4 holding registers (FC 16), 1 client, %zu requests: median %.0f us, p99 %.0f us\n",
              wrtt.size(), pct(wrtt, 0.5), pct(wrtt, 0.99));
  std::printf("  16 clients x 100 Hz: %ld reads, %ld errors, round trip median %.0f us, p99 %.0f us\n", poll_reads,
              poll_errors, pct(poll_rtt, 0.5), pct(poll_rtt, 0.99));
  std::printf("  frame wall_ms without polling: median %.2f, p99 %.2f (%zu frames, %.1f fps)\n", pct(without, 0.5),
              pct(without, 0.99), without.size(), without_n / (2 * phase_s));
  std::printf("  frame wall_ms with 16 clients polling: median %.2f, p99 %.2f (%zu frames, %.1f fps)\n",
              pct(with, 0.5), pct(with, 0.99), with.size(), with_n / (2 * phase_s));
  std::printf("  effect on the median frame time: %+.1f %%\n", 100.0 * (pct(with, 0.5) / pct(without, 0.5) - 1.0));
  std::filesystem::remove_all(out);
  return 0;
}
}  // namespace

int main(int argc, char** argv) {
  std::string connect, size = "640x480";
  int clients = 0, reads = 2000;
  double rate = 100.0, seconds = 2.0, phase_s = 5.0;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    const char* v = k + 1 < argc ? argv[k + 1] : "";
    if (a == "--connect") connect = v, ++k;
    else if (a == "--poll") clients = std::atoi(v), ++k;
    else if (a == "--rate") rate = std::atof(v), ++k;
    else if (a == "--seconds") seconds = std::atof(v), ++k;
    else if (a == "--size") size = v, ++k;
    else if (a == "--phase-s") phase_s = std::max(1.0, std::atof(v)), ++k;
    else if (a == "--reads") reads = std::max(10, std::atoi(v)), ++k;
    else {
      std::fprintf(stderr, "bench_modbus: unknown option %s\n", a.c_str());
      return 2;
    }
  }
  if (!connect.empty()) {
    const auto colon = connect.rfind(':');
    if (colon == std::string::npos || clients < 1) {
      std::fprintf(stderr, "bench_modbus: --connect HOST:PORT needs --poll N\n");
      return 2;
    }
    return poll_mode({connect.substr(0, colon), std::atoi(connect.c_str() + colon + 1)}, clients, rate, seconds);
  }
  const std::string bin_dir = std::filesystem::path(argv[0]).parent_path().string();
  return bench_mode(bin_dir.empty() ? "." : bin_dir, size, phase_s, reads);
}
#else
#include <cstdio>
int main() {
  std::puts("bench_modbus: built without Modbus (IG_WITH_MODBUS=OFF)");
  return 0;
}
#endif
