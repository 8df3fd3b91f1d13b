#pragma once
// Captured frames as PNG through OpenImageIO.

#include <cstdint>
#include <string>
#include <vector>

namespace ig::capture {

// rgba: width*height*4 bytes, top row first. Throws std::runtime_error naming the file.
void write_png_rgba(const std::string& path, const std::vector<std::uint8_t>& rgba, int width, int height);

}  // namespace ig::capture
