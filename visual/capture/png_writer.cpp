#include "capture/png_writer.h"

#include <OpenImageIO/imageio.h>

#include <stdexcept>

namespace ig::capture {

void write_png_rgba(const std::string& path, const std::vector<std::uint8_t>& rgba, int width, int height) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw std::runtime_error(path + ": cannot create PNG writer: " + OIIO::geterror());
  // Store RGB: the alpha channel is always opaque.
  std::vector<std::uint8_t> rgb(size_t(width) * height * 3);
  for (size_t p = 0, n = size_t(width) * height; p < n; ++p)
    for (int c = 0; c < 3; ++c) rgb[p * 3 + c] = rgba[p * 4 + c];
  OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
  if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::UINT8, rgb.data()) || !out->close())
    throw std::runtime_error(path + ": cannot write PNG: " + out->geterror());
}

}  // namespace ig::capture
