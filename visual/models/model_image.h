#pragma once
// A texture decoded to 8-bit RGBA, ready for one glTexImage2D call. No GL.

#include <cstdint>
#include <string>
#include <vector>

namespace ig::models {

struct Image {
  std::string name;  // the image's name, else its file name; may be empty
  int width = 0;
  int height = 0;
  // width * height * 4 bytes, rows first to last as stored in the file (the
  // first row is texture coordinate v = 0, glTF's convention, so it is
  // uploaded first). 16-bit images keep their high byte; grey and grey-alpha
  // images are expanded to RGBA.
  std::vector<std::uint8_t> rgba;
};

}  // namespace ig::models
