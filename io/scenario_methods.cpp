// The scenario's per-method settings: render.twolevel and each baseline's
// section (render.roam, render.quadtree, render.geomipmap, render.chunked,
// render.cdlod); docs/scenario.md.
#include "io/scenario_json.h"

namespace ig::io::scenario_json {
namespace {

options::TwoLevelOptions parse_twolevel(const json& j, const std::string& path) {
  require_object(j, path);
  check_keys(j, path, {"level0_budget", "a1", "a2", "alpha", "beta", "max_level1", "band_stride", "band", "eye_guard", "level0_envelope", "level0_error", "predict_size", "horizon_culling"});
  options::TwoLevelOptions t;
  if (j.contains("level0_budget")) {
    const auto& b = j["level0_budget"];
    t.level0_budget = b.is_string() && b.get<std::string>() == "auto"
                          ? 0
                          : static_cast<int>(get_integer(b, child(path, "level0_budget") + " (a number or \"auto\")",
                                                        options::TwoLevelOptions::kMinLevel0Budget,
                                                        options::TwoLevelOptions::kMaxLevel0Budget));
  }
  if (j.contains("a1")) t.a1 = get_number(j["a1"], child(path, "a1"));
  if (j.contains("a2")) t.a2 = get_number(j["a2"], child(path, "a2"));
  if (const auto why = options::TwoLevelOptions::check_thresholds(t.a1, t.a2))  // "aN must ..."
    fail(child(path, why->substr(0, 2)), why->substr(3));
  if (j.contains("alpha")) t.alpha = get_positive(j["alpha"], child(path, "alpha"), options::TwoLevelOptions::kMaxAlpha);
  if (j.contains("beta"))
    t.gaussian_beta = get_choice(j["beta"], child(path, "beta"), {"linear", "gaussian"}) == "gaussian";
  if (j.contains("max_level1")) {
    const std::string p = child(path, "max_level1");
    const long long n = get_integer(j["max_level1"], p, 33, 1025);
    if (((n - 1) & (n - 2)) != 0) fail(p, "must be one of 33, 65, 129, 257, 513, 1025" + got(j["max_level1"]));
    t.max_level1 = static_cast<int>(n);
  }
  if (j.contains("band_stride")) t.band_stride = static_cast<int>(get_integer(j["band_stride"], child(path, "band_stride"), 1, 64));
  if (j.contains("band")) t.band_inline = get_choice(j["band"], child(path, "band"), {"inline", "target"}) == "inline";
  if (j.contains("level0_error"))
    t.level0_whole_error = get_choice(j["level0_error"], child(path, "level0_error"), {"midpoint", "whole"}) == "whole";
  if (j.contains("eye_guard")) t.eye_guard = get_bool(j["eye_guard"], child(path, "eye_guard"));
  if (j.contains("level0_envelope"))
    t.level0_envelope = get_bool(j["level0_envelope"], child(path, "level0_envelope"));
  if (j.contains("predict_size")) t.predict_size = get_bool(j["predict_size"], child(path, "predict_size"));
  if (j.contains("horizon_culling")) t.horizon_culling = get_bool(j["horizon_culling"], child(path, "horizon_culling"));
  return t;
}

// {"KEY": number in (0, kMaxBaselineKnob]} sections of one knob each.
double knob(const json& section, const std::string& path, const char* key, double value) {
  return section.contains(key) ? get_positive(section[key], child(path, key), options::kMaxBaselineKnob) : value;
}

}  // namespace

void parse_method_options(const json& render, const std::string& path, RenderSpec& r) {
  if (render.contains("twolevel")) r.twolevel = parse_twolevel(render["twolevel"], child(path, "twolevel"));
  auto section = [&](const char* name, std::initializer_list<std::string_view> keys) -> const json* {
    if (!render.contains(name)) return nullptr;
    const std::string p = child(path, name);
    require_object(render[name], p);
    check_keys(render[name], p, keys);
    return &render[name];
  };
  // Every baseline's horizon_culling: on or off (options/method_options.h).
  auto culling = [&](const json& j, const char* name, bool& on) {
    if (j.contains("horizon_culling")) on = get_bool(j["horizon_culling"], child(child(path, name), "horizon_culling"));
  };
  if (const json* j = section("roam", {"tau_px", "horizon_culling"})) {
    r.roam.tau_px = knob(*j, child(path, "roam"), "tau_px", r.roam.tau_px);
    culling(*j, "roam", r.roam.horizon_culling);
  }
  if (const json* j = section("quadtree", {"c1", "c2", "horizon_culling"})) {
    const std::string p = child(path, "quadtree");
    r.quadtree.c1 = knob(*j, p, "c1", r.quadtree.c1);
    if (j->contains("c2")) r.quadtree.c2 = get_number_in((*j)["c2"], child(p, "c2"), 0.0, options::kMaxBaselineKnob);
    culling(*j, "quadtree", r.quadtree.horizon_culling);
  }
  if (const json* j = section("geomipmap", {"tau_px", "horizon_culling"})) {
    r.geomipmap.tau_px = knob(*j, child(path, "geomipmap"), "tau_px", r.geomipmap.tau_px);
    culling(*j, "geomipmap", r.geomipmap.horizon_culling);
  }
  if (const json* j = section("chunked", {"tau_px", "horizon_culling"})) {
    r.chunked.tau_px = knob(*j, child(path, "chunked"), "tau_px", r.chunked.tau_px);
    culling(*j, "chunked", r.chunked.horizon_culling);
  }
  if (const json* j = section("cdlod", {"lod0_range", "horizon_culling"})) {
    r.cdlod.lod0_range = knob(*j, child(path, "cdlod"), "lod0_range", r.cdlod.lod0_range);
    culling(*j, "cdlod", r.cdlod.horizon_culling);
  }
}

}  // namespace ig::io::scenario_json
