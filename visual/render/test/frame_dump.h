#pragma once
// For a look at what a GL test rendered: with the environment variable `env`
// naming a folder, an RGBA frame is written there as <name>.png (alpha
// forced opaque: the coverage codes would make it translucent).

#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "capture/png_writer.h"

inline void dump_frame(const char* env, std::vector<std::uint8_t> rgba, int w, int h, const std::string& name) {
  const char* dir = std::getenv(env);
  if (!dir || !*dir) return;
  for (size_t p = 3; p < rgba.size(); p += 4) rgba[p] = 255;
  ig::capture::write_png_rgba(std::string(dir) + "/" + name + ".png", rgba, w, h);
}
