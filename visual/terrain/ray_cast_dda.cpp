// The baseline ray cast without acceleration (cast_ray_dda,
// terrain/ray_cast.h): a 2D DDA over the cells under the ray, with the same
// watertight test as cast_ray (terrain/ray_cast_kernel.h).
#include "terrain/ray_cast_kernel.h"

namespace ig::terrain {

using namespace ray_kernel;

std::optional<RayHit> cast_ray_dda(const Heightfield& hf, glm::dvec3 origin, glm::dvec3 dir, double max_t) {
  if (hf.width < 2 || hf.height < 2 || !valid_spacing(hf)) return std::nullopt;
  if (!hf.has_samples()) return std::nullopt;
  Ray r;  // height range from finalize_stats() (only scales a tiny slack; 0 if never called)
  if (!make_ray(origin, dir, max_t, scene_scale(hf, hf.min_m, hf.max_m), r)) return std::nullopt;
  if (auto h = origin_on_surface(hf, r)) return h;
  const int ncx = hf.width - 1, ncy = hf.height - 1;
  const double sx = hf.spacing_x_m, sy = hf.spacing_y_m;

  // Clip to the 2D footprint (no height bounds: deliberately naive).
  double enter = r.t_lo, exit = max_t;
  if (!slab(r, 0, 0.0, ncx * sx, enter, exit) || !slab(r, 1, 0.0, ncy * sy, enter, exit)) return std::nullopt;
  if (!overlaps(r, enter, exit)) return std::nullopt;

  double best = max_t;
  bool found = false;
  int hit_i = -1, hit_j = -1;
  auto test = [&](int i, int j) {
    if (i < 0 || j < 0 || i >= ncx || j >= ncy) return;
    if (intersect_cell(hf, r, i, j, best)) {
      found = true;
      hit_i = i;
      hit_j = j;
    }
  };
  // Cells [a, b] whose closed footprint contains coordinate c: both sides
  // when c is on (or within rounding of) a grid line.
  auto cells_at = [](double c, double s, int n, int& a, int& b) {
    const double g = c / s, k = std::round(g);
    a = b = std::clamp(int(std::floor(g)), 0, n - 1);
    if (std::abs(g - k) <= 1e-9 * std::max(1.0, std::abs(g)) && k > 0 && k < n) {
      a = int(k) - 1;
      b = int(k);
    }
  };

  if (r.par[0] && r.par[1]) {  // vertical ray: the cell(s) under the origin
    int i0, i1, j0, j1;
    cells_at(r.o.x, sx, ncx, i0, i1);
    cells_at(r.o.y, sy, ncy, j0, j1);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) test(i, j);
    if (!found) return std::nullopt;
    return make_hit(r, best, hit_i, hit_j);
  }

  const glm::dvec3 p = r.o + std::max(enter, 0.0) * r.d;
  int i = std::clamp(int(std::floor(p.x / sx)), 0, ncx - 1);
  int j = std::clamp(int(std::floor(p.y / sy)), 0, ncy - 1);
  const int si = r.par[0] ? 0 : (r.d.x > 0 ? 1 : -1);
  const int sj = r.par[1] ? 0 : (r.d.y > 0 ? 1 : -1);
  auto next_x = [&] { return si == 0 ? kInf : (double(i + (si > 0)) * sx - r.o.x) * r.inv[0]; };
  auto next_y = [&] { return sj == 0 ? kInf : (double(j + (sj > 0)) * sy - r.o.y) * r.inv[1]; };
  for (int guard = 0; guard < ncx + ncy + 4; ++guard) {
    test(i, j);
    const double tx = next_x(), ty = next_y();
    const double tn = std::min(tx, ty);
    if (found && best < tn - slack(r, tn)) break;  // later cells start after tn
    if (tn - slack(r, tn) > exit) break;
    const double tie = slack(r, tn);
    if (tx < ty - tie) {
      i += si;
    } else if (ty < tx - tie) {
      j += sj;
    } else {  // through (or within rounding of) a corner: also test both side cells
      test(i + si, j);
      test(i, j + sj);
      i += si;
      j += sj;
    }
    if (i < 0 || j < 0 || i >= ncx || j >= ncy) break;
  }
  if (!found) return std::nullopt;
  return make_hit(r, best, hit_i, hit_j);
}

}  // namespace ig::terrain
