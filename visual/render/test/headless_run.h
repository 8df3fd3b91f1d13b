#pragma once
// Run options of the GL tests: an off-screen frame of w x h pixels with the
// build's shaders; method "" keeps the scenario's.

#include <optional>
#include <string>

#include "session/scenario_runner.h"

inline ig::session::RunOptions headless_run(int w, int h, const std::string& method = "") {
  ig::session::RunOptions o;
  o.width = w;
  o.height = h;
  o.headless = true;
  o.shader_dir = std::string(IG_BIN_DIR) + "/shaders";
  if (!method.empty()) o.method = method;
  return o;
}
