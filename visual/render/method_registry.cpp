// The one place that maps method names to implementations.
#include <stdexcept>
#include <string>

#include "lod/level0_budget.h"
#include "render/cdlod_method.h"
#include "render/chunked_method.h"
#include "render/geomipmap_method.h"
#include "render/quadtree_method.h"
#include "render/reference_method.h"
#include "render/roam_method.h"
#include "render/terrain_method.h"
#include "render/twolevel_method.h"

namespace ig::render {

double pixels_per_radian(const Camera& camera, int viewport_height_px) {
  return lod::pixels_per_radian(viewport_height_px, camera.fov_y_deg);
}

std::vector<std::string> method_names() {
  return {"twolevel", "reference", "roam", "geomipmap", "chunked", "quadtree", "cdlod"};
}

namespace {

[[noreturn]] void throw_unknown(const std::string& name) {
  std::string choices;
  for (const auto& n : method_names()) choices += (choices.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown method '" + name + "' (available: " + choices + ")");
}

// A baseline built from its options, the knob (when given) in place of its default.
template <class Method, class Options>
std::unique_ptr<TerrainMethod> with_knob(const TerrainScene& scene, const std::string& shader_dir, Options options,
                                         double Options::*knob_field, std::optional<double> knob) {
  if (knob) options.*knob_field = *knob;
  return std::make_unique<Method>(scene, shader_dir, options);
}

}  // namespace

std::unique_ptr<TerrainMethod> make_method(const std::string& name, TerrainScene& scene,
                                           const std::string& shader_dir, const MethodOptions& options,
                                           std::optional<double> knob) {
  // Beyond the GL texture limit only the two-level method draws (it reads
  // full resolution through the scene's height window); the others would
  // need the whole DEM in one texture.
  if (scene.overview_step() > 1 && name != "twolevel") {
    const auto& hf = scene.heightfield();
    throw std::invalid_argument("method '" + name + "' cannot draw " + hf.source + " (" + std::to_string(hf.width) +
                                "x" + std::to_string(hf.height) + "): it needs the whole DEM in one texture and the GL "
                                "height-texture limit is " + std::to_string(scene.texture_limit()) + "; use the twolevel method");
  }
  if (scene.heightfield().paged && name != "twolevel") {  // over the memory budget
    const auto& hf = scene.heightfield();
    throw std::invalid_argument("method '" + name + "' cannot draw " + hf.source + " (" + std::to_string(hf.width) +
                                "x" + std::to_string(hf.height) + "): its heights are paged (over "
                                "terrain.memory_budget_mb) and the method needs them whole; use the twolevel method");
  }
  // Imagery beyond one texture: the other methods drape its overview (the
  // scene's imagery texture, up to the texture limit); only the two-level
  // method keeps a full-resolution imagery window on its Level1.
  if (name == "reference") return std::make_unique<ReferenceMethod>(scene, shader_dir);
  if (name == "twolevel") {
    TwoLevelOptions o = options.twolevel;
    if (knob) o.level0_budget = int(*knob);
    return std::make_unique<TwoLevelMethod>(scene, shader_dir, o);
  }
  if (name == "roam") return with_knob<RoamMethod>(scene, shader_dir, options.roam, &options::RoamOptions::tau_px, knob);
  if (name == "quadtree")
    return with_knob<QuadtreeMethod>(scene, shader_dir, options.quadtree, &options::QuadtreeOptions::c1, knob);
  if (name == "geomipmap")
    return with_knob<GeoMipMapMethod>(scene, shader_dir, options.geomipmap, &options::GeoMipMapOptions::tau_px, knob);
  if (name == "chunked")
    return with_knob<ChunkedMethod>(scene, shader_dir, options.chunked, &options::ChunkedOptions::tau_px, knob);
  if (name == "cdlod")
    return with_knob<CdlodMethod>(scene, shader_dir, options.cdlod, &options::CdlodOptions::lod0_range, knob);
  throw_unknown(name);
}

std::optional<ErrorKnob> default_knob(const std::string& name, const MethodOptions& options) {
  // Names, units and values as each method's knob() reports them.
  if (name == "reference") return std::nullopt;
  if (name == "twolevel") {
    const int budget = options.twolevel.level0_budget;  // 0: what the method picks alone
    return ErrorKnob{"level0_budget", "triangles", double(budget > 0 ? budget : lod::level0_budget_for_display(0.0))};
  }
  if (name == "roam") return ErrorKnob{"tau_px", "px", options.roam.tau_px};
  if (name == "quadtree") return ErrorKnob{"C1", "", options.quadtree.c1};
  if (name == "geomipmap") return ErrorKnob{"tau_px", "px", options.geomipmap.tau_px};
  if (name == "chunked") return ErrorKnob{"tau_px", "px", options.chunked.tau_px};
  if (name == "cdlod") return ErrorKnob{"lod0_range", "samples", options.cdlod.lod0_range};
  throw_unknown(name);
}

std::vector<double> knob_sweep(const std::string& name) {
  if (name == "twolevel") return {2048, 32768, 131072, 524288, 1048576, 2097152};
  // The coarse ends reach the two-level default's horizon error on the
  // Table 2 flight, so matched-error times are interpolated, not bounded.
  if (name == "geomipmap" || name == "chunked") return {64, 32, 16, 8, 4, 2, 1};  // tau_px
  if (name == "roam") return {64, 32, 16, 8, 4, 2, 1, 0.5};                       // tau_px
  if (name == "quadtree") return {0.125, 0.25, 0.5, 1, 2, 4, 8};                  // C1 (C2 fixed at 30)
  if (name == "cdlod") return {8, 16, 32, 64, 128, 256, 512};                     // lod0_range, samples
  return {};
}

}  // namespace ig::render
