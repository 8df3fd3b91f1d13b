#pragma once
// What the height and imagery window tests share (issue 16): a path of
// small, diagonal, seam-crossing, clamped and jumping steps, and the check
// after every move that it uploaded only what scrolled in and that the
// wrap-around window holds exactly the full texture's texels.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <vector>

#include <glm/common.hpp>
#include <glm/vec2.hpp>

namespace window_checks {

// Centres in DEM samples over a 97 x 75 DEM.
inline const std::vector<glm::ivec2>& test_path() {
  static const std::vector<glm::ivec2> path = {{40, 30}, {41, 30}, {41, 31}, {44, 35}, {43, 34}, {30, 20}, {31, 21},
                                               {0, 0},   {3, 2},   {96, 74}, {90, 70}, {50, 40}, {52, 37}, {48, 44},
                                               {63, 47}, {64, 48}, {79, 63}, {60, 30}, {60, 30}};
  return path;
}

// The wrap-around window's texels (size x size, `channels` values a texel)
// equal the full texture's (full_w wide) over the window at origin o.
template <class T>
void expect_window_holds(const std::vector<T>& texels, int size, glm::ivec2 o, const std::vector<T>& full, int full_w,
                         int channels) {
  for (int j = o.y; j < o.y + size; ++j)
    for (int i = o.x; i < o.x + size; ++i)
      for (int k = 0; k < channels; ++k)
        if (texels[(static_cast<std::size_t>(j % size) * size + i % size) * channels + k] !=
            full[(static_cast<std::size_t>(j) * full_w + i) * channels + k]) {
          ADD_FAILURE() << "texel " << i << "," << j << " channel " << k << " differs";
          return;
        }
}

// A size x size window over a full_w-wide texture of `channels` values a
// texel: move(c) centres it and returns the texels uploaded, origin() says
// where it is, read_window() reads its texture; `each` checks more per step.
// Returns the texels uploaded in all.
template <class T>
long long expect_window_follows_path(int size, int full_w, const std::vector<T>& full, int channels,
                                     const std::function<long long(glm::ivec2)>& move,
                                     const std::function<glm::ivec2()>& origin,
                                     const std::function<std::vector<T>()>& read_window,
                                     const std::function<void(glm::ivec2 centre, glm::ivec2 origin)>& each = {}) {
  long long total = 0;
  glm::ivec2 prev{};
  bool first = true;
  for (const glm::ivec2 c : test_path()) {
    SCOPED_TRACE(testing::Message() << "centre " << c.x << "," << c.y);
    const long long uploaded = move(c);
    const glm::ivec2 o = origin();
    // Only what scrolled in: the window's area minus its overlap with the last one.
    const glm::ivec2 d = first ? glm::ivec2(size) : glm::abs(o - prev);
    const long long overlap = static_cast<long long>(std::max(size - d.x, 0)) * std::max(size - d.y, 0);
    EXPECT_EQ(uploaded, first ? size * size : size * size - overlap);
    total += uploaded;
    first = false;
    prev = o;
    if (each) each(c, o);
    expect_window_holds(read_window(), size, o, full, full_w, channels);
  }
  return total;
}

}  // namespace window_checks
