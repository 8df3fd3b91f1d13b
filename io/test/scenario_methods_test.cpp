// The per-method sections of a scenario's render object: render.twolevel
// (the two-level method's settings) and each baseline's knob (render.roam,
// render.quadtree, render.geomipmap, render.chunked, render.cdlod).
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "io/scenario.h"

namespace {

const char* kTwoLevelBase = R"({"terrain": {"generator": {"size": 65}}, "path": {"keys": [{"t": 0, "position": [0, 0, 100]}]},
  "render": {"twolevel": %s}})";

// The parse error of a scenario text ("no error" when it parses).
std::string parse_error(const std::string& text) {
  try {
    ig::io::parse_scenario(text);
  } catch (const ig::io::ScenarioError& e) {
    return std::string(e.what());
  }
  return "no error";
}

std::string with_twolevel(const std::string& body) {
  char buf[1024];
  std::snprintf(buf, sizeof buf, kTwoLevelBase, body.c_str());
  return buf;
}

TEST(ScenarioTwoLevel, DefaultsAreThePapers) {
  const auto s = ig::io::parse_scenario(with_twolevel("{}"));
  EXPECT_EQ(s.render.method, "twolevel");
  EXPECT_EQ(s.render.twolevel.level0_budget, 0);  // "auto"
  EXPECT_DOUBLE_EQ(s.render.twolevel.a1, 0.5);
  EXPECT_DOUBLE_EQ(s.render.twolevel.a2, 0.8);
}

TEST(ScenarioTwoLevel, Level0BudgetIsANumberOrAuto) {
  EXPECT_EQ(ig::io::parse_scenario(with_twolevel(R"({"level0_budget": "auto"})")).render.twolevel.level0_budget, 0);
  EXPECT_THROW(ig::io::parse_scenario(with_twolevel(R"({"level0_budget": "fine"})")), ig::io::ScenarioError);
  EXPECT_THROW(ig::io::parse_scenario(with_twolevel(R"({"level0_budget": 1})")), ig::io::ScenarioError);
}

TEST(ScenarioTwoLevel, ReadsEveryKey) {
  const auto s = ig::io::parse_scenario(with_twolevel(
      R"({"level0_budget": 4096, "a1": 0.4, "a2": 0.9, "alpha": 500, "beta": "gaussian", "max_level1": 513, "band_stride": 1, "band": "target", "level0_error": "whole"})"));
  const auto& t = s.render.twolevel;
  EXPECT_EQ(t.level0_budget, 4096);
  EXPECT_DOUBLE_EQ(t.a1, 0.4);
  EXPECT_DOUBLE_EQ(t.a2, 0.9);
  EXPECT_DOUBLE_EQ(t.alpha, 500);
  EXPECT_TRUE(t.gaussian_beta);
  EXPECT_EQ(t.max_level1, 513);
  EXPECT_EQ(t.band_stride, 1);
  EXPECT_FALSE(t.band_inline);
  EXPECT_TRUE(t.level0_whole_error);
}

TEST(ScenarioTwoLevel, BadValuesNameTheirKey) {
  auto error_of = [](const std::string& body) { return parse_error(with_twolevel(body)); };
  EXPECT_NE(error_of(R"({"a1": 0.9, "a2": 0.5})").find("render.twolevel.a2"), std::string::npos);
  EXPECT_NE(error_of(R"({"max_level1": 100})").find("render.twolevel.max_level1"), std::string::npos);
  EXPECT_NE(error_of(R"({"beta": "cubic"})").find("render.twolevel.beta"), std::string::npos);
  EXPECT_NE(error_of(R"({"budget": 1})").find("render.twolevel.budget"), std::string::npos);
}

}  // namespace

namespace {

std::string with_render(const std::string& render) {
  return R"({"terrain": {"generator": {"size": 65}}, "path": {"keys": [{"t": 0, "position": [0, 0, 100]}]},
  "render": )" + render + "}";
}

TEST(ScenarioMethods, BaselineKnobsDefaultToTheOptionsStructs) {
  const auto r = ig::io::parse_scenario(with_render("{}")).render;
  EXPECT_DOUBLE_EQ(r.roam.tau_px, ig::options::RoamOptions{}.tau_px);
  EXPECT_DOUBLE_EQ(r.quadtree.c1, ig::options::QuadtreeOptions{}.c1);
  EXPECT_DOUBLE_EQ(r.quadtree.c2, ig::options::QuadtreeOptions{}.c2);
  EXPECT_DOUBLE_EQ(r.geomipmap.tau_px, ig::options::GeoMipMapOptions{}.tau_px);
  EXPECT_DOUBLE_EQ(r.chunked.tau_px, ig::options::ChunkedOptions{}.tau_px);
  EXPECT_DOUBLE_EQ(r.cdlod.lod0_range, ig::options::CdlodOptions{}.lod0_range);
}

TEST(ScenarioMethods, ReadsEveryBaselineKnob) {
  const auto r = ig::io::parse_scenario(with_render(
      R"({"roam": {"tau_px": 4}, "quadtree": {"c1": 0.5, "c2": 10}, "geomipmap": {"tau_px": 8},
          "chunked": {"tau_px": 16}, "cdlod": {"lod0_range": 64}})")).render;
  EXPECT_DOUBLE_EQ(r.roam.tau_px, 4);
  EXPECT_DOUBLE_EQ(r.quadtree.c1, 0.5);
  EXPECT_DOUBLE_EQ(r.quadtree.c2, 10);
  EXPECT_DOUBLE_EQ(r.geomipmap.tau_px, 8);
  EXPECT_DOUBLE_EQ(r.chunked.tau_px, 16);
  EXPECT_DOUBLE_EQ(r.cdlod.lod0_range, 64);
  const auto m = ig::io::parse_scenario(with_render(R"({"cdlod": {"lod0_range": 64}})")).render.method_options();
  EXPECT_DOUBLE_EQ(m.cdlod.lod0_range, 64);
}

TEST(ScenarioMethods, BadBaselineValuesNameTheirKey) {
  auto error_of = [](const std::string& render) { return parse_error(with_render(render)); };
  EXPECT_NE(error_of(R"({"roam": {"tau_px": 0}})").find("render.roam.tau_px"), std::string::npos);
  EXPECT_NE(error_of(R"({"quadtree": {"c2": -1}})").find("render.quadtree.c2"), std::string::npos);
  EXPECT_NE(error_of(R"({"cdlod": {"range": 1}})").find("render.cdlod.range"), std::string::npos);
  EXPECT_NE(error_of(R"({"chunked": 2})").find("render.chunked"), std::string::npos);
}

}  // namespace
