// ig: the image generator. Subcommands dispatch to tools/ig/*_command.cpp.
#include <cstdio>
#include <string>
#include <vector>

#include "commands.h"

namespace {
constexpr const char* kHelp =
    "ig - terrain image generator\n"
    "usage:\n"
    "  ig run SCENARIO.json [--out DIR] [--frames N] [--size WxH] [--method NAME] [--headless|--window]\n"
    "  ig serve [--config FILE] [--udp ADDR:PORT] [--cigi ADDR:PORT --cigi-reply HOST:PORT] [--fgfdm ADDR:PORT]\n"
    "           [--multicast GROUP] [--channel NAME] [--frames N | --seconds S] [--record FILE] [--out DIR]\n"
    "           [--latency smooth|latest|sync] [--modbus ADDR:PORT] [--can IFNAME]\n"
    "  ig send SCENARIO.json --to ADDR:PORT [--protocol native|cigi|fgfdm] [--rate HZ] [--loss P] ...\n"
    "  ig bench SCENARIO.json [--methods LIST|all] [--sweep] [--frames N] [--size WxH] [--fov DEG]\n"
    "           [--error-samples N] [--match-px PX] [--out DIR]   (error against run time, docs/bench.md)\n"
    "  ig info DEMFILE [--encoding auto|terrain-rgb|png16] [--scale S] [--offset O] [--spacing M]\n"
    "  ig help\n"
    "Every command prints its full usage with --help.\n";
}

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fputs(kHelp, stderr);
    return 2;
  }
  const std::string cmd = argv[1];
  const std::vector<std::string> args(argv + 2, argv + argc);
  if (cmd == "run") return ig::app::run_run_command(args);
  if (cmd == "info") return ig::app::run_info_command(args);
  if (cmd == "serve") return ig::app::run_serve_command(args);
  if (cmd == "send") return ig::app::run_send_command(args);
  if (cmd == "bench") return ig::app::run_bench_command(args);
  if (cmd == "help" || cmd == "--help" || cmd == "-h") {
    std::fputs(kHelp, stdout);
    return 0;
  }
  std::fprintf(stderr, "ig: unknown command '%s'\n%s", cmd.c_str(), kHelp);
  return 2;
}
