#pragma once
// Every LOD method's own settings (docs/baselines.md, docs/twolevel.md), one
// struct per method, for every place that sets them: the scenario file
// (render.twolevel, render.roam, ...; io/scenario_methods.cpp), ig bench
// (a method's default knob, read here without building the method) and the
// methods themselves (render::make_method). Plain data, no GL.

#include "options/twolevel_options.h"

namespace ig::options {

// Horizon culling: every method's horizon_culling (the two-level's in
// twolevel_options.h) leaves out what it draws behind nearer terrain
// (lod/horizon_culling.h over the method's own boxes); the picture is the
// same either way. On by default for all, so methods compare fairly.

// Baseline "roam": view-dependent ROAM rebuilt every frame.
struct RoamOptions {
  double tau_px = 2.0;  // split while a triangle's projected wedgie exceeds this, > 0
  // Viewport height tau refers to until the method is told the real one.
  int viewport_height_px = 1024;
  bool horizon_culling = true;  // over its own boxes (the note above)
};

// Baseline "quadtree": the restricted quadtree of Röttger et al.
struct QuadtreeOptions {
  double c1 = 2.0;   // the knob: larger = finer everywhere, > 0
  double c2 = 30.0;  // roughness below 1 / C2 sample spacings counts as flat, >= 0
  bool horizon_culling = true;  // over its own boxes (the note above)
};

// Baseline "geomipmap": de Boer's geometrical mipmapping.
struct GeoMipMapOptions {
  double tau_px = 2.0;  // largest projected error of a block's level, pixels, > 0
  bool horizon_culling = true;  // over its own boxes (the note above)
};

// Baseline "chunked": Ulrich's chunked LOD.
struct ChunkedOptions {
  double tau_px = 2.0;  // largest projected error of a drawn chunk, pixels, > 0
  bool horizon_culling = true;  // over its own boxes (the note above)
};

// Baseline "cdlod": Strugar's continuous distance-dependent LOD.
struct CdlodOptions {
  double lod0_range = 128.0;  // range of the finest LOD, DEM sample spacings, > 0
  bool horizon_culling = true;  // over its own boxes (the note above)
};

// Upper bound of every baseline knob the scenario accepts (keeps arithmetic finite).
inline constexpr double kMaxBaselineKnob = 1e6;

struct MethodOptions {
  MethodOptions() = default;
  // The two-level settings with every baseline at its defaults.
  MethodOptions(const TwoLevelOptions& t) : twolevel(t) {}  // NOLINT(google-explicit-constructor)
  MethodOptions(const TwoLevelOptions& t, const RoamOptions& r, const QuadtreeOptions& q, const GeoMipMapOptions& g,
                const ChunkedOptions& c, const CdlodOptions& d)
      : twolevel(t), roam(r), quadtree(q), geomipmap(g), chunked(c), cdlod(d) {}

  TwoLevelOptions twolevel;
  RoamOptions roam;
  QuadtreeOptions quadtree;
  GeoMipMapOptions geomipmap;
  ChunkedOptions chunked;
  CdlodOptions cdlod;

  // Horizon culling on or off for every method at once.
  void set_horizon_culling(bool on) {
    twolevel.horizon_culling = roam.horizon_culling = quadtree.horizon_culling = geomipmap.horizon_culling =
        chunked.horizon_culling = cdlod.horizon_culling = on;
  }
};

}  // namespace ig::options
