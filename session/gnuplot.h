#pragma once
// Runs a gnuplot script that writes one PNG: the frame-time plot of every
// run and ig bench's error-vs-time plot. A missing or failing gnuplot is
// reported, never fatal: the run's other outputs stand.

#include <string>

namespace ig::session {

// Writes `script` beside png_path (png_path + ".gp") and runs gnuplot on it.
// True when png_path was written (the script is then removed); else says on
// stderr "COMMAND: WHAT not written (...)" with gnuplot's output, keeping
// the script to look at.
bool run_gnuplot(const std::string& script, const std::string& png_path, const std::string& command,
                 const std::string& what);

}  // namespace ig::session
