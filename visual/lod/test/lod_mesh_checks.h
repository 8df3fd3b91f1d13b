#pragma once
// Checks shared by the view-dependent LOD structure tests (ROAM, quadtree):
// the eyes they are checked from, watertightness of a triangle list of DEM
// sample indices, and the reference surface the error bounds are measured
// against, and the checks both run on a tessellator: its claimed bound, its
// culling and its refusal of bad input. Their small test terrains are in
// lod_test_terrain.h.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <glm/gtc/type_precision.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "lod_test_terrain.h"
#include "terrain/heightfield.h"

namespace lod_checks {

// Over the middle, low near the north-west corner, outside the DEM and high,
// just inside the east edge.
inline std::vector<glm::dvec3> eyes_for(const ig::terrain::Heightfield& hf) {
  const double ex = hf.extent_x_m(), ey = hf.extent_y_m();
  return {
      {0.5 * ex, 0.5 * ey, hf.max_m + 100.0},
      {0.05 * ex, 0.9 * ey, hf.min_m + 30.0},
      {ex + 2000.0, -3000.0, hf.max_m + 5000.0},
      {0.97 * ex, 0.4 * ey, hf.max_m + 1.0},
  };
}

// Empty when the triangles tile the DEM exactly: every triangle
// counter-clockwise with positive area and inside the DEM, every edge used
// once in each direction or (on the DEM's border) once, and the areas summing
// to the DEM's. Otherwise the first problem found.
inline std::string watertight(const std::vector<glm::u16vec2>& v, int w, int h) {
  std::ostringstream err;
  if (v.size() % 3 != 0) return "vertex count not a multiple of 3";
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  auto key = [](glm::u16vec2 p) { return (std::uint32_t(p.y) << 16) | p.x; };
  long long twice_area = 0;
  for (size_t t = 0; t < v.size(); t += 3) {
    const glm::ivec2 a(v[t]), b(v[t + 1]), c(v[t + 2]);
    for (const auto& p : {a, b, c})
      if (p.x >= w || p.y >= h) {
        err << "vertex (" << p.x << "," << p.y << ") outside the DEM";
        return err.str();
      }
    const long long cross = (long long)(b.x - a.x) * (c.y - a.y) - (long long)(b.y - a.y) * (c.x - a.x);
    if (cross <= 0) {
      err << "triangle " << t / 3 << " (" << a.x << "," << a.y << ") (" << b.x << "," << b.y << ") (" << c.x << ","
          << c.y << ") is not counter-clockwise";
      return err.str();
    }
    twice_area += cross;
    const glm::u16vec2 tri[3] = {v[t], v[t + 1], v[t + 2]};
    for (int e = 0; e < 3; ++e) ++directed[{key(tri[e]), key(tri[(e + 1) % 3])}];
  }
  for (const auto& [edge, count] : directed) {
    const glm::ivec2 p(edge.first & 0xffff, edge.first >> 16), q(edge.second & 0xffff, edge.second >> 16);
    if (count != 1) {
      err << "edge (" << p.x << "," << p.y << ")-(" << q.x << "," << q.y << ") used " << count << " times one way";
      return err.str();
    }
    if (directed.count({edge.second, edge.first})) continue;
    const bool border = (p.x == q.x && (p.x == 0 || p.x == w - 1)) || (p.y == q.y && (p.y == 0 || p.y == h - 1));
    if (!border) {
      err << "edge (" << p.x << "," << p.y << ")-(" << q.x << "," << q.y
          << ") has no triangle on its other side (crack or T-junction)";
      return err.str();
    }
  }
  if (twice_area != 2LL * (w - 1) * (h - 1)) {
    err << "triangles cover " << twice_area / 2.0 << " cells, the DEM " << (w - 1) * (h - 1);
    return err.str();
  }
  return "";
}

// The reference surface (render/grid_mesh: cells split along (i,j)-(i+1,j+1))
// at a point given in half-sample units (2x, 2y): samples and cell centres.
inline double reference_at_half(const ig::terrain::Heightfield& hf, int x2, int y2) {
  if (x2 % 2 == 0 && y2 % 2 == 0) return hf.at(x2 / 2, y2 / 2);
  const int i = x2 / 2, j = y2 / 2;  // cell centre (both odd)
  return 0.5 * (double(hf.at(i, j)) + hf.at(i + 1, j + 1));
}

// Largest |reference - plane through the triangle's corners| over the samples
// and cell centres inside the triangle (where the piecewise-linear difference
// takes its extremes: the LODs' edges are axis-aligned or at 45 degrees), and
// the largest of that over the eye distance when `eye` is given (metres).
struct Deviation {
  double metres = 0.0;
  double ratio = 0.0;
};
inline Deviation triangle_deviation(const ig::terrain::Heightfield& hf, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c,
                                    const glm::dvec3* eye = nullptr) {
  Deviation d;
  const glm::ivec2 mn = glm::min(a, glm::min(b, c)), mx = glm::max(a, glm::max(b, c));
  const double ha = hf.at(a.x, a.y), hb = hf.at(b.x, b.y), hc = hf.at(c.x, c.y);
  const double den = double(b.x - a.x) * (c.y - a.y) - double(b.y - a.y) * (c.x - a.x);
  for (int y2 = 2 * mn.y; y2 <= 2 * mx.y; ++y2)
    for (int x2 = 2 * mn.x; x2 <= 2 * mx.x; ++x2) {
      if ((x2 & 1) != (y2 & 1)) continue;  // edge midpoints of cells: not needed
      const double px = 0.5 * x2, py = 0.5 * y2;
      // Barycentric coordinates.
      const double l1 = ((px - a.x) * (c.y - a.y) - (py - a.y) * (c.x - a.x)) / den;
      const double l2 = ((b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x)) / den;
      const double l0 = 1.0 - l1 - l2;
      if (l0 < -1e-9 || l1 < -1e-9 || l2 < -1e-9) continue;
      const double ref = reference_at_half(hf, x2, y2);
      const double dev = std::abs(ref - (l0 * ha + l1 * hb + l2 * hc));
      d.metres = std::max(d.metres, dev);
      if (eye) {
        const glm::dvec3 p(px * hf.spacing_x_m, py * hf.spacing_y_m, ref);
        const double dist = std::sqrt((p.x - eye->x) * (p.x - eye->x) + (p.y - eye->y) * (p.y - eye->y) +
                                      (p.z - eye->z) * (p.z - eye->z));
        d.ratio = std::max(d.ratio, dist > 0 ? dev / dist : (dev > 0 ? 1e30 : 0.0));
      }
    }
  return d;
}

// The largest deviation ratio (metres over eye distance) over a triangle
// list: what a tessellator's claimed error bound must cover.
inline double worst_deviation_ratio(const ig::terrain::Heightfield& hf, const std::vector<glm::u16vec2>& v,
                                    const glm::dvec3& eye) {
  double worst = 0.0;
  for (size_t t = 0; t < v.size(); t += 3)
    worst = std::max(worst, triangle_deviation(hf, v[t], v[t + 1], v[t + 2], &eye).ratio);
  return worst;
}

// For each DEM, eye (eyes_for) and knob, the selection select(tessellator,
// eye, knob) returns claims a max_error_ratio that covers every output
// triangle's deviation ratio.
template <class Tessellator, class Select>
void expect_bound_covers_every_output_point(const std::vector<ig::terrain::Heightfield>& dems,
                                            std::initializer_list<double> knobs, const std::string& knob_label,
                                            Select select) {
  for (const auto& hf : dems) {
    Tessellator t(hf);
    for (const auto& eye : eyes_for(hf))
      for (double knob : knobs) {
        const auto sel = select(t, eye, knob);
        const double worst = worst_deviation_ratio(hf, sel.vertices, eye);
        const double claimed = sel.stats.max_error_ratio;
        EXPECT_TRUE(std::isfinite(claimed));
        EXPECT_LE(worst, claimed * (1 + 1e-6) + 1e-9)
            << knob_label << " " << knob << " eye " << eye.x << "," << eye.y;
      }
  }
}

// Stepping the knob from least to most accurate, select(tessellator, eye,
// knob) of a 257^2 landscape seen from 300 m over its highest point gives
// strictly more triangles and a claimed bound never larger each time.
template <class Tessellator, class Select>
void expect_more_triangles_and_no_larger_bound(std::initializer_list<double> knobs, const std::string& knob_label,
                                               Select select) {
  const auto hf = synthetic(257);
  Tessellator t(hf);
  const glm::dvec3 eye(0.2 * hf.extent_x_m(), 0.3 * hf.extent_y_m(), hf.max_m + 300.0);
  long long prev_tris = 0;
  double prev_bound = std::numeric_limits<double>::infinity();
  for (double knob : knobs) {
    const auto s = select(t, eye, knob).stats;
    EXPECT_GT(s.triangles, prev_tris) << knob_label << " " << knob;
    EXPECT_LE(s.max_error_ratio, prev_bound) << knob_label << " " << knob;
    prev_tris = s.triangles;
    prev_bound = s.max_error_ratio;
  }
}

// A tessellator of a 129^2 landscape seen from 50 m over its highest point
// at its centre, selected by `select(tessellator, eye, in_view)` whole (all:
// its counts) and with a view of everything east of the eye only (east),
// which must draw fewer than 3/4 of the triangles and cull something. The
// rest is for the tessellator's own checks.
template <class Tessellator>
struct EastOfEyeCulling {
  using Selection = decltype(std::declval<Tessellator&>().select(glm::dvec3(), 1.0, 1.0));

  template <class Select>
  explicit EastOfEyeCulling(Select select)
      : all(select(tessellator, eye, {}).stats),
        east(select(tessellator, eye, [](const glm::dvec3&, const glm::dvec3& hi) { return hi.x >= 0.0; })) {
    EXPECT_LT(east.stats.triangles, all.triangles * 3 / 4);
    EXPECT_GT(east.stats.culled, 0);
  }

  ig::terrain::Heightfield hf = synthetic(129);
  Tessellator tessellator{hf};
  glm::dvec3 eye{0.5 * hf.extent_x_m(), 0.5 * hf.extent_y_m(), hf.max_m + 50.0};
  decltype(Selection::stats) all;
  Selection east;
};

// The tessellator refuses a DEM of tiny_w x tiny_h samples and one with no
// spacing; `select_bad(tessellator)` then checks its refusals of bad
// selection arguments on a 17^2 landscape.
template <class Tessellator, class SelectBad>
void expect_rejects_bad_input(int tiny_w, int tiny_h, SelectBad select_bad) {
  ig::terrain::Heightfield tiny;
  tiny.width = tiny_w;
  tiny.height = tiny_h;
  tiny.heights.assign(std::size_t(tiny_w) * tiny_h, 0.0f);
  EXPECT_THROW(Tessellator{tiny}, std::invalid_argument);
  ig::terrain::Heightfield flat_spacing = synthetic(17);
  flat_spacing.spacing_x_m = 0.0;
  EXPECT_THROW(Tessellator{flat_spacing}, std::invalid_argument);
  const auto hf = synthetic(17);
  Tessellator t(hf);
  select_bad(t);
}

}  // namespace lod_checks
