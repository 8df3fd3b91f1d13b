#pragma once
#include <string>

namespace ig::session {

// Plots frame time over the run (frames.csv -> frametime.png) with gnuplot.
// Returns false (and says why on stderr) when gnuplot is missing or fails;
// the run's other outputs stand.
bool plot_frame_times(const std::string& csv_path, const std::string& png_path, const std::string& title,
                      double budget_ms);

}  // namespace ig::session
