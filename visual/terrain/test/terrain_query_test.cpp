// TerrainQuery: HOT against the DEM file read directly with GDAL and its own
// triangles (independent of the loader and of the query), line of sight
// against a brute force over every triangle near the line, and the Earth
// curvature model against a finely sampled bent line.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <random>
#include <stdexcept>
#include <vector>

#include <gdal_priv.h>
#include <glm/geometric.hpp>

#include "io/filter/geodesy.h"
#include "lod/level0_height_query.h"
#include "lod/roam_level0_mesh.h"
#include "terrain/dem_loader.h"
#include "terrain/earth_curvature.h"
#include "terrain/terrain_query.h"

namespace {

namespace fs = std::filesystem;
using glm::dvec3;
using ig::terrain::Heightfield;
using ig::terrain::TerrainQuery;
using LD = long double;

const char* dem_dir() {
  const char* d = std::getenv("IG_DEM_DIR");
  return (d && *d) ? d : nullptr;
}

const Heightfield& sierra() {
  static const Heightfield hf =
      ig::terrain::load_dem((fs::path(dem_dir()) / "sierra_nevada_3arcsec_4097.tif").string());
  return hf;
}

// The file as GDAL gives it: north-up rows, pixel-corner geotransform.
struct RawDem {
  int w = 0, h = 0;
  double gt[6]{};
  std::vector<float> v;
  float at(int col, int row) const { return v[std::size_t(row) * w + col]; }
};

RawDem read_raw(const std::string& path) {
  GDALAllRegister();
  std::unique_ptr<GDALDataset> ds(GDALDataset::FromHandle(GDALOpen(path.c_str(), GA_ReadOnly)));
  RawDem r;
  if (!ds) return r;
  r.w = ds->GetRasterXSize();
  r.h = ds->GetRasterYSize();
  ds->GetGeoTransform(r.gt);
  r.v.resize(std::size_t(r.w) * r.h);
  if (ds->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, r.w, r.h, r.v.data(), r.w, r.h, GDT_Float32, 0, 0) != CE_None)
    r.v.clear();
  return r;
}

// The height of the drawn surface at (lon, lat) from the raw file: samples
// at pixel centres; each quad cut along its south-west -> north-east
// diagonal (the renderer's (i,j)-(i+1,j+1) with row 0 south), the plane of
// the triangle holding the point. Linear interpolation is affine-invariant,
// so pixel units give the same height as metres.
double raw_surface(const RawDem& d, double lon, double lat) {
  const LD px = (LD(lon) - d.gt[0]) / d.gt[1] - 0.5L;  // fractional column of sample centres
  const LD py = (LD(lat) - d.gt[3]) / d.gt[5] - 0.5L;  // fractional row, north-first
  const int c = int(std::floor(px)), r = int(std::floor(py));
  const LD u = px - c;         // east within the quad
  const LD v = 1.0L - (py - r);  // north within the quad (row r is its north side)
  // Corners: sw = (c, r+1), se = (c+1, r+1), nw = (c, r), ne = (c+1, r).
  const LD sw = d.at(c, r + 1), se = d.at(c + 1, r + 1), nw = d.at(c, r), ne = d.at(c + 1, r);
  // South-east triangle (sw, se, ne) when u >= v, else north-west (sw, ne, nw).
  if (u >= v) return double(sw + (se - sw) * u + (ne - se) * v);
  return double(sw + (nw - sw) * v + (ne - nw) * u);
}

TEST(TerrainQuerySierra, HotAtRandomGeodeticPointsMatchesTheDemTriangles) {
  if (!dem_dir()) GTEST_SKIP() << "IG_DEM_DIR not set: real-DEM tests skipped";
  const Heightfield& hf = sierra();
  const RawDem raw = read_raw((fs::path(dem_dir()) / "sierra_nevada_3arcsec_4097.tif").string());
  ASSERT_EQ(raw.w, hf.width);
  ASSERT_FALSE(raw.v.empty());
  ASSERT_TRUE(hf.georef);
  // Geodetic -> local the way live poses are placed (io/filter/geodesy.h).
  const auto grid = ig::io::geo::GeographicGrid::make(hf.georef->grid_to_crs, hf.spacing_x_m, hf.spacing_y_m);
  ASSERT_TRUE(grid);
  const TerrainQuery q(hf, ig::terrain::kEarthRadiusM);
  // Sample-centre bounds of the file.
  const double lon0 = raw.gt[0] + 0.5 * raw.gt[1], lon1 = raw.gt[0] + (raw.w - 0.5) * raw.gt[1];
  const double lat1 = raw.gt[3] + 0.5 * raw.gt[5], lat0 = raw.gt[3] + (raw.h - 0.5) * raw.gt[5];
  std::mt19937 rng(15);
  std::uniform_real_distribution<double> ulon(lon0 + 1e-6, lon1 - 1e-6), ulat(lat0 + 1e-6, lat1 - 1e-6);
  double worst = 0.0;
  for (int k = 0; k < 20000; ++k) {
    const double lon = ulon(rng), lat = ulat(rng);
    const glm::dvec2 xy = grid->to_local(lat, lon);
    const auto s = q.surface_at(xy.x, xy.y);
    ASSERT_TRUE(s) << lat << " " << lon;
    worst = std::max(worst, std::abs(s->height_m - raw_surface(raw, lon, lat)));
    EXPECT_GT(s->normal.z, 0.0);
    EXPECT_NEAR(glm::length(s->normal), 1.0, 1e-12);
  }
  std::printf("HOT vs the DEM file's triangles, 20000 random points: max error %.3g m\n", worst);
  EXPECT_LT(worst, 0.01);
  // Outside the footprint: no answer.
  const glm::dvec2 out = grid->to_local(lat1 + 0.01, lon0);
  EXPECT_FALSE(q.surface_at(out.x, out.y));
}

// Where the two-level method draws Level0 (outside Level1), the picture is a
// coarse ROAM mesh, not the full-resolution surface the queries answer from:
// how far apart they are on the Sierra DEM (docs/host-services.md). Level0's
// vertices are DEM samples, so there they agree.
TEST(TerrainQuerySierra, Level0DiffersFromTheFullResolutionSurface) {
  if (!dem_dir()) GTEST_SKIP() << "IG_DEM_DIR not set: real-DEM tests skipped";
  const Heightfield& hf = sierra();
  const TerrainQuery q(hf, 0.0);
  for (int budget : {2048, 8192, 32768}) {
    const auto mesh = ig::lod::build_level0_mesh(hf, ig::lod::Level0Options{budget, 0.0, ig::terrain::kEarthRadiusM});
    const ig::lod::Level0HeightQuery level0(mesh, hf.width, hf.height);
    std::mt19937 rng(budget);
    std::uniform_real_distribution<double> ui(0, hf.width - 1), uj(0, hf.height - 1);
    std::vector<double> diff;
    for (int k = 0; k < 100000; ++k) {
      const double i = ui(rng), j = uj(rng);
      diff.push_back(std::abs(level0.height_at(i, j) - q.surface_at(i * hf.spacing_x_m, j * hf.spacing_y_m)->height_m));
    }
    std::sort(diff.begin(), diff.end());
    double mean = 0;
    for (double d : diff) mean += d / double(diff.size());
    std::printf("Level0 %d triangles vs full resolution, 100000 random points: mean %.1f m, median %.1f m, "
                "p95 %.1f m, max %.1f m\n",
                mesh.triangle_count, mean, diff[diff.size() / 2], diff[diff.size() * 95 / 100], diff.back());
    EXPECT_GT(diff.back(), 1.0);  // coarse enough to matter for ground contact
    double at_vertices = 0;
    for (const glm::ivec2 s : mesh.samples)
      at_vertices = std::max(at_vertices, std::abs(level0.height_at(s.x, s.y) - hf.at(s.x, s.y)));
    EXPECT_LT(at_vertices, 1e-3);
  }
}

// ------------------------------------------------------------ line of sight

struct LV {
  LD x, y, z;
};
LV sub(LV a, LV b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
LV cross(LV a, LV b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
LD dot(LV a, LV b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// Nearest hit in [t0, t1] along unit d from o over every triangle of every
// cell whose box the segment's footprint touches (Moller-Trumbore, long
// double, edges included). -1 when none.
// radius > 0: every sample lowered by its curvature drop from o's (x, y), as
// the renderer draws the terrain for an eye at o.
LD brute_force(const Heightfield& hf, dvec3 o_in, dvec3 d_in, double t0, double t1, double radius = 0.0) {
  const LV o{o_in.x, o_in.y, o_in.z}, d{d_in.x, d_in.y, d_in.z};
  const double xa = std::min(o_in.x + t0 * d_in.x, o_in.x + t1 * d_in.x), xb = std::max(o_in.x + t0 * d_in.x, o_in.x + t1 * d_in.x);
  const double ya = std::min(o_in.y + t0 * d_in.y, o_in.y + t1 * d_in.y), yb = std::max(o_in.y + t0 * d_in.y, o_in.y + t1 * d_in.y);
  const int i0 = std::max(0, int(std::floor(xa / hf.spacing_x_m)) - 1), i1 = std::min(hf.width - 2, int(xb / hf.spacing_x_m) + 1);
  const int j0 = std::max(0, int(std::floor(ya / hf.spacing_y_m)) - 1), j1 = std::min(hf.height - 2, int(yb / hf.spacing_y_m) + 1);
  auto vtx = [&](int i, int j) {
    const LD x = LD(i) * hf.spacing_x_m, y = LD(j) * hf.spacing_y_m;
    LD z = hf.at(i, j);
    if (radius > 0) {  // R - sqrt(R^2 - d^2)
      const LD d2 = (x - o.x) * (x - o.x) + (y - o.y) * (y - o.y), R = radius;
      z -= d2 / (R + std::sqrt(R * R - d2));
    }
    return LV{x, y, z};
  };
  LD best = -1;
  auto tri = [&](LV a, LV b, LV c) {
    const LV e1 = sub(b, a), e2 = sub(c, a), p = cross(d, e2);
    const LD det = dot(e1, p);
    if (det == 0) return;
    const LV s = sub(o, a);
    const LD u = dot(s, p) / det;
    if (u < -1e-12L || u > 1 + 1e-12L) return;
    const LV qv = cross(s, e1);
    const LD v = dot(d, qv) / det;
    if (v < -1e-12L || u + v > 1 + 1e-12L) return;
    const LD t = dot(e2, qv) / det;
    if (t >= LD(t0) - 1e-9L && t <= LD(t1) + 1e-9L && (best < 0 || t < best)) best = t;
  };
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      tri(vtx(i, j), vtx(i + 1, j), vtx(i + 1, j + 1));
      tri(vtx(i, j), vtx(i + 1, j + 1), vtx(i, j + 1));
    }
  return best;
}

Heightfield rough_hf(unsigned seed) {
  Heightfield hf;
  hf.width = hf.height = 97;
  hf.spacing_x_m = 30.0;
  hf.spacing_y_m = 25.0;
  hf.heights.resize(std::size_t(hf.width) * hf.height);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> noise(-20.f, 20.f);
  for (int j = 0; j < hf.height; ++j)
    for (int i = 0; i < hf.width; ++i)
      hf.ref(i, j) = float(300.0 + 120.0 * std::sin(i * 0.21) * std::cos(j * 0.17) + noise(rng));
  hf.finalize_stats();
  return hf;
}

void expect_matches_brute_force(const TerrainQuery& q, dvec3 from, dvec3 dir, double lo, double hi, int& hits,
                                int& misses) {
  const dvec3 d = glm::normalize(dir);
  const auto got = q.ray(from, dir, lo, hi);
  const LD want = brute_force(q.heightfield(), from, d, lo, hi);
  if (want < 0) {
    EXPECT_FALSE(got) << "from " << from.x << "," << from.y << "," << from.z << " range " << got->range_m;
    ++misses;
    return;
  }
  ++hits;
  ASSERT_TRUE(got) << "brute force hits at " << double(want);
  EXPECT_NEAR(got->range_m, double(want), 1e-6 * (1.0 + double(want)));
  const dvec3 p = from + got->range_m * d;
  EXPECT_NEAR(got->point.x, p.x, 1e-6);
  EXPECT_NEAR(got->point.y, p.y, 1e-6);
  EXPECT_NEAR(got->point.z, p.z, 1e-6);
  const auto s = q.surface_at(got->point.x, got->point.y);
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->height_m, got->point.z, 1e-6);
}

TEST(TerrainQueryLos, RandomRaysMatchBruteForce) {
  const Heightfield hf = rough_hf(3);
  const TerrainQuery q(hf, 0.0);
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> ux(0, hf.extent_x_m()), uy(0, hf.extent_y_m()), uz(200, 700);
  std::uniform_real_distribution<double> ang(0, 2 * M_PI), el(-0.6, 0.3), rng01(0, 1);
  int hits = 0, misses = 0;
  for (int k = 0; k < 3000; ++k) {
    const dvec3 from(ux(rng), uy(rng), uz(rng));
    const double a = ang(rng), e = el(rng);
    const dvec3 dir(std::cos(e) * std::sin(a), std::cos(e) * std::cos(a), std::sin(e));
    const double lo = rng01(rng) < 0.3 ? 300.0 * rng01(rng) : 0.0;
    const double hi = lo + 2500.0 * rng01(rng);
    expect_matches_brute_force(q, from, dir, lo, hi, hits, misses);
  }
  std::printf("random rays: %d hits, %d misses\n", hits, misses);
  EXPECT_GT(hits, 500);
  EXPECT_GT(misses, 300);
}

// With curvature: the first hit on the triangles between the lowered samples
// (a small radius so the drop is large on this 2.9 km terrain).
TEST(TerrainQueryLos, CurvedRaysMatchBruteForceOnLoweredTriangles) {
  const Heightfield hf = rough_hf(11);
  const double R = 30000.0;
  const TerrainQuery q(hf, R);
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> ux(0, hf.extent_x_m()), uy(0, hf.extent_y_m()), uz(300, 700);
  std::uniform_real_distribution<double> ang(0, 2 * M_PI), el(-0.4, 0.05), rng01(0, 1);
  int hits = 0, misses = 0, differ = 0;
  const TerrainQuery flat(hf, 0.0);
  for (int k = 0; k < 2000; ++k) {
    const dvec3 from(ux(rng), uy(rng), uz(rng));
    const double a = ang(rng), e = el(rng);
    const dvec3 d(std::cos(e) * std::sin(a), std::cos(e) * std::cos(a), std::sin(e));
    const double hi = 3000.0 * rng01(rng);
    const auto got = q.ray(from, d, 0.0, hi);
    const LD want = brute_force(hf, from, d, 0.0, hi, R);
    if (want < 0) {
      EXPECT_FALSE(got);
      ++misses;
      continue;
    }
    ++hits;
    ASSERT_TRUE(got);
    EXPECT_NEAR(got->range_m, double(want), 1e-6 * (1.0 + double(want)));
    // Given back on the flat DEM at the same (x, y).
    EXPECT_NEAR(got->point.x, from.x + got->range_m * d.x, 1e-6);
    EXPECT_NEAR(got->point.z, q.surface_at(got->point.x, got->point.y)->height_m, 1e-9);
    const auto f = flat.ray(from, d, 0.0, hi);
    if (!f || std::abs(f->range_m - got->range_m) > 1.0) ++differ;
  }
  std::printf("curved rays: %d hits, %d misses, %d differ from flat by > 1 m\n", hits, misses, differ);
  EXPECT_GT(hits, 300);
  EXPECT_GT(misses, 300);
  EXPECT_GT(differ, 100);
}

// Rays aimed a hair above (miss) or below (hit) a sample that stands above
// its neighbours along the ray, at 0.5 degrees and shallower.
TEST(TerrainQueryLos, GrazingRaysOverPeaks) {
  Heightfield hf = rough_hf(5);
  hf.ref(40, 50) = 900.0f;  // an isolated spike: the ray can only touch its top
  hf.finalize_stats();
  const TerrainQuery q(hf, 0.0);
  const dvec3 peak(40 * hf.spacing_x_m, 50 * hf.spacing_y_m, 900.0);
  int hits = 0, misses = 0;
  for (double el_deg : {0.5, 0.1, 0.01}) {
    for (double az_deg = 0; az_deg < 360; az_deg += 15) {
      const double el = el_deg * M_PI / 180, az = az_deg * M_PI / 180;
      const dvec3 d(std::cos(el) * std::sin(az), std::cos(el) * std::cos(az), -std::sin(el));
      for (double above : {1e-4, -1e-4}) {
        const dvec3 from = peak + dvec3(0, 0, above) - 400.0 * d;  // 400 m before the spike
        const auto got = q.ray(from, d, 0.0, 399.0 + 1.0);
        const LD want = brute_force(hf, from, d, 0.0, 400.0);
        if (above > 0) {  // a miss over the top, whatever lies around
          EXPECT_LT(want, 0);
          EXPECT_FALSE(got) << "el " << el_deg << " az " << az_deg;
          ++misses;
        } else {  // clips the spike's side just under the top
          ASSERT_GE(want, 0);
          ASSERT_TRUE(got);
          EXPECT_NEAR(got->range_m, double(want), 1e-6);
          EXPECT_GT(got->range_m, 399.0 - 1e-4 / std::tan(el) - 1.0);
          ++hits;
        }
      }
    }
  }
  EXPECT_EQ(hits, 72);
  EXPECT_EQ(misses, 72);
}

TEST(TerrainQueryLos, SegmentsAndMisses) {
  const Heightfield hf = rough_hf(7);
  const TerrainQuery q(hf, 0.0);
  const dvec3 high(1000, 1000, 2000), low(1500, 1300, 100);
  // Down through the terrain: hits, within the segment.
  const auto down = q.segment(high, low);
  ASSERT_TRUE(down);
  EXPECT_LT(down->range_m, glm::length(low - high));
  EXPECT_NEAR(down->range_m, double(brute_force(hf, high, glm::normalize(low - high), 0, glm::length(low - high))), 1e-6);
  // Both ends above every sample: clear.
  EXPECT_FALSE(q.segment(dvec3(100, 100, 1000), dvec3(2500, 2000, 1100)));
  // Pointing away from the terrain, and leaving the footprint.
  EXPECT_FALSE(q.ray(high, dvec3(0, 0, 1), 0, 1e6));
  EXPECT_FALSE(q.ray(dvec3(-100, 50, 1000), dvec3(-1, 0, 0), 0, 1e6));
  // Straight down from outside the footprint: nothing under it.
  EXPECT_FALSE(q.ray(dvec3(-1, 50, 1000), dvec3(0, 0, -1), 0, 1e6));
  // Straight down, unbounded: the HOT.
  const auto v = q.ray(dvec3(777, 555, 3000), dvec3(0, 0, -1), 0, std::numeric_limits<double>::infinity());
  ASSERT_TRUE(v);
  EXPECT_NEAR(v->range_m, 3000 - q.surface_at(777, 555)->height_m, 1e-9);
  // A minimum range past the hit: the next crossing (from below, coming out) or nothing.
  const auto past = q.ray(high, low - high, down->range_m + 1.0, glm::length(low - high));
  if (past) {
    EXPECT_GT(past->range_m, down->range_m + 1.0);
  }
  // A shared pyramid answers the same; one from another grid is refused.
  const ig::terrain::HeightPyramid pyramid(hf);
  const TerrainQuery shared(hf, pyramid, 0.0);
  EXPECT_EQ(shared.segment(high, low)->range_m, down->range_m);
  const Heightfield small = rough_hf(1);
  Heightfield smaller = small;
  smaller.width = smaller.height = 9;
  smaller.heights.resize(81);
  EXPECT_THROW(TerrainQuery(smaller, pyramid, 0.0), std::invalid_argument);
  // Bad input.
  EXPECT_FALSE(q.ray(high, dvec3(0), 0, 10));
  EXPECT_FALSE(q.ray(high, dvec3(1, 0, 0), 10, 5));
  EXPECT_FALSE(q.ray(dvec3(NAN, 0, 0), dvec3(1, 0, 0), 0, 5));
  EXPECT_FALSE(q.surface_at(NAN, 5));
}

// With curvature the line bends up by drop(d) in the DEM frame: compare with
// the bent line sampled every 0.25 m (first sample at or under the surface)
// on the real DEM at the Earth's radius.
TEST(TerrainQueryLos, CurvedLinesMatchSampledBentLine) {
  if (!dem_dir()) GTEST_SKIP() << "IG_DEM_DIR not set: real-DEM tests skipped";
  const Heightfield& hf = sierra();
  const TerrainQuery q(hf, ig::terrain::kEarthRadiusM);
  const TerrainQuery flat(hf, 0.0);
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> ux(0.3 * hf.extent_x_m(), 0.7 * hf.extent_x_m()),
      uy(0.3 * hf.extent_y_m(), 0.7 * hf.extent_y_m()), ang(0, 2 * M_PI), el(-0.25, -0.02);
  int compared = 0, differs_from_flat = 0;
  for (int k = 0; k < 60; ++k) {
    const double x = ux(rng), y = uy(rng);
    const dvec3 from(x, y, q.surface_at(x, y)->height_m + 1500.0);
    const double a = ang(rng), e = el(rng);
    const dvec3 d(std::cos(e) * std::sin(a), std::cos(e) * std::cos(a), std::sin(e));
    const auto got = q.ray(from, d, 0.0, 60000.0);
    double want = -1;
    const double h = std::hypot(d.x, d.y);
    for (double t = 0; t <= 60000.0; t += 0.25) {
      const dvec3 p = from + t * d + dvec3(0, 0, ig::terrain::curvature_drop(t * h, ig::terrain::kEarthRadiusM));
      const auto s = q.surface_at(p.x, p.y);
      if (!s) break;
      if (p.z <= s->height_m) {
        want = t;
        break;
      }
    }
    if (want < 0) {
      EXPECT_FALSE(got);
      continue;
    }
    ASSERT_TRUE(got);
    ++compared;
    // 0.25 m sampling; the drawn triangles lie within 0.2 mm of the smooth drop.
    EXPECT_NEAR(got->range_m, want, 0.25 + 1e-3 / std::abs(std::sin(e)));
    const auto s = q.surface_at(got->point.x, got->point.y);
    EXPECT_NEAR(got->point.z, s->height_m, 1e-6);
    const auto f = flat.ray(from, d, 0.0, 60000.0);
    if (!f || std::abs(f->range_m - got->range_m) > 1.0) ++differs_from_flat;
  }
  std::printf("curved lines compared: %d, %d differ from the flat answer by > 1 m\n", compared, differs_from_flat);
  EXPECT_GT(compared, 40);
  EXPECT_GT(differs_from_flat, 0);  // the curvature is really applied
}

}  // namespace
