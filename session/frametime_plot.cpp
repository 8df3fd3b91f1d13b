#include "session/frametime_plot.h"

#include <sstream>

#include "session/gnuplot.h"

namespace ig::session {

bool plot_frame_times(const std::string& csv_path, const std::string& png_path, const std::string& title,
                      double budget_ms) {
  std::ostringstream gp;
  gp << "set datafile separator ','\n"
     << "set terminal pngcairo size 1000,500 noenhanced\n"
     << "set output '" << png_path << "'\n"
     << "set title '" << title << "'\n"
     << "set xlabel 'frame'\nset ylabel 'frame time (ms)'\nset grid\nset key top right\n"
     << "set yrange [0:*]\n"
     << "plot '" << csv_path << "' using 'frame':'wall_ms' with lines lw 1.5 title 'wall ms (glFinish)', "
     << "     '' using 'frame':'terrain_ms' with lines lw 1 title 'terrain passes', "
     << budget_ms << " with lines dt 2 lc rgb 'red' title 'budget " << budget_ms << " ms'\n";
  return run_gnuplot(gp.str(), png_path, "ig", "frame-time plot");
}

}  // namespace ig::session
