#include "session/frametime_plot.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace ig::session {

bool plot_frame_times(const std::string& csv_path, const std::string& png_path, const std::string& title,
                      double budget_ms) {
  const std::string script_path = png_path + ".gp";
  {
    std::ofstream gp(script_path);
    gp << "set datafile separator ','\n"
       << "set terminal pngcairo size 1000,500 noenhanced\n"
       << "set output '" << png_path << "'\n"
       << "set title '" << title << "'\n"
       << "set xlabel 'frame'\nset ylabel 'frame time (ms)'\nset grid\nset key top right\n"
       << "set yrange [0:*]\n"
       << "plot '" << csv_path << "' using 'frame':'wall_ms' with lines lw 1.5 title 'wall ms (glFinish)', "
       << "     '' using 'frame':'terrain_ms' with lines lw 1 title 'terrain passes', "
       << budget_ms << " with lines dt 2 lc rgb 'red' title 'budget " << budget_ms << " ms'\n";
  }
  const std::string cmd = "gnuplot '" + script_path + "' 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) {
    std::cerr << "ig: cannot run gnuplot for " << png_path << "\n";
    return false;
  }
  char buf[256];
  std::string output;
  while (fgets(buf, sizeof buf, p)) output += buf;
  const int rc = pclose(p);
  std::filesystem::remove(script_path);
  if (rc != 0 || !std::filesystem::exists(png_path)) {
    std::cerr << "ig: frame-time plot not written (is gnuplot installed? tools/setup.sh installs it): "
              << output << "\n";
    return false;
  }
  return true;
}

}  // namespace ig::session
