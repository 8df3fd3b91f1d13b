// The scenario's environment section: environment.time_utc (ISO 8601 UTC)
// and how it sits beside render.sun_direction; environment.clouds.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "scenario_error.h"

#include "io/scenario.h"
#include "io/utc_time.h"

namespace {

using namespace ig::io;

std::string with_environment(const std::string& environment, const std::string& render = "{}") {
  return R"({ "terrain": {"generator": {"size": 257, "origin": [37.3, -118.6]}},
              "path": {"keys": [{"t": 0, "position": [0, 0, 100]}]},
              "render": )" +
         render + R"(, "environment": )" + environment + "}";
}

TEST(EnvironmentScenario, TimeUtcIsRead) {
  const Scenario s = parse_scenario(with_environment(R"({"time_utc": "2026-06-21T14:30:05Z"})"));
  ASSERT_TRUE(s.render.shading.time_utc.has_value());
  const auto& t = *s.render.shading.time_utc;
  EXPECT_EQ(t.year, 2026);
  EXPECT_EQ(t.month, 6);
  EXPECT_EQ(t.day, 21);
  EXPECT_EQ(t.hour, 14);
  EXPECT_EQ(t.minute, 30);
  EXPECT_DOUBLE_EQ(t.second, 5.0);
  EXPECT_FALSE(s.render.shading.sun_direction.has_value());
}

TEST(EnvironmentScenario, OtherFormsOfUtc) {
  std::string why;
  const auto fraction = parse_utc_time("2024-02-29T23:59:59.25Z", why);  // a leap day
  ASSERT_TRUE(fraction.has_value()) << why;
  EXPECT_DOUBLE_EQ(fraction->second, 59.25);
  const auto no_seconds = parse_utc_time("2026-12-21T06:15Z", why);
  ASSERT_TRUE(no_seconds.has_value()) << why;
  EXPECT_EQ(no_seconds->minute, 15);
  EXPECT_DOUBLE_EQ(no_seconds->second, 0.0);
  const auto offset_zero = parse_utc_time("2026-12-21T06:15:00+00:00", why);
  ASSERT_TRUE(offset_zero.has_value()) << why;
  EXPECT_EQ(*offset_zero, *no_seconds);
}

TEST(EnvironmentScenario, SunDirectionStaysBesideTime) {
  // Both given: the scenario keeps both; the direction overrides (docs/scenario.md).
  const Scenario s =
      parse_scenario(with_environment(R"({"time_utc": "2026-06-21T14:30:00Z"})", R"({"sun_direction": [0, 0, 2]})"));
  ASSERT_TRUE(s.render.shading.sun_direction.has_value());
  EXPECT_FLOAT_EQ(s.render.shading.sun_direction->z, 1.0f);
  EXPECT_TRUE(s.render.shading.time_utc.has_value());
}

TEST(EnvironmentScenario, BadTimesNameTheKeyAndTheReason) {
  struct Case {
    const char* environment;
    std::vector<std::string> expect;
  };
  const std::vector<Case> cases = {
      {R"({"time_utc": "2026-06-21 14:30:00Z"})", {"environment.time_utc", "ISO 8601", "2026-06-21 14:30:00Z"}},
      {R"({"time_utc": "2026-06-21"})", {"environment.time_utc", "time of day is missing"}},
      {R"({"time_utc": "2026-06-21T14:30:00"})", {"environment.time_utc", "zone is missing"}},
      {R"({"time_utc": "2026-06-21T14:30:00+02:00"})", {"environment.time_utc", "must be in UTC"}},
      {R"({"time_utc": "2026-13-01T00:00:00Z"})", {"environment.time_utc", "month 13"}},
      {R"({"time_utc": "2026-02-29T00:00:00Z"})", {"environment.time_utc", "day 29", "2026-02"}},
      {R"({"time_utc": "2026-04-31T00:00:00Z"})", {"environment.time_utc", "day 31"}},
      {R"({"time_utc": "2026-06-21T24:00:00Z"})", {"environment.time_utc", "hour 24"}},
      {R"({"time_utc": "2026-06-21T12:60:00Z"})", {"environment.time_utc", "minute 60"}},
      {R"({"time_utc": "2016-12-31T23:59:60Z"})", {"environment.time_utc", "second 60", "leap"}},
      {R"({"time_utc": "2026-06-21T12:00:00.Z"})", {"environment.time_utc", "decimal point"}},
      {R"({"time_utc": "1850-06-21T12:00:00Z"})", {"environment.time_utc", "year 1850", "1900..2100"}},
      {R"({"time_utc": "noon"})", {"environment.time_utc", "ISO 8601"}},
      {R"({"time_utc": ""})", {"environment.time_utc", "ISO 8601"}},
      {R"({"time_utc": 1750000000})", {"environment.time_utc", "must be a string"}},
      {R"({"time": "2026-06-21T14:30:00Z"})", {"environment.time", "unknown key", "time_utc"}},
      {R"("2026-06-21T14:30:00Z")", {"environment", "must be an object"}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.environment);
    const std::string msg = scenario_error_of(with_environment(c.environment));
    for (const std::string& want : c.expect)
      EXPECT_NE(msg.find(want), std::string::npos) << "message: " << msg << "\nwanted: " << want;
  }
}

TEST(EnvironmentScenario, CloudLayersAreRead) {
  const Scenario s = parse_scenario(with_environment(R"({"clouds": [
      {"type": "stratus", "coverage_pct": 100, "base_m": 1500, "thickness_m": 300, "transition_m": 40,
       "visibility_m": 80},
      {"type": "cumulus", "coverage_pct": 25, "base_m": 2500, "wind_mps": 10, "wind_from_deg": 270,
       "scud_pct": 20}]})"));
  const auto& c = s.render.shading.clouds;
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].type, ig::options::CloudType::Stratus);
  EXPECT_EQ(c[0].id, 1);
  EXPECT_DOUBLE_EQ(c[0].coverage, 1.0);
  EXPECT_DOUBLE_EQ(c[0].base_m, 1500.0);
  EXPECT_DOUBLE_EQ(c[0].thickness_m, 300.0);
  EXPECT_DOUBLE_EQ(c[0].transition_m, 40.0);
  EXPECT_DOUBLE_EQ(c[0].visibility_m, 80.0);
  EXPECT_EQ(c[1].type, ig::options::CloudType::Cumulus);
  EXPECT_EQ(c[1].id, 2);
  EXPECT_DOUBLE_EQ(c[1].coverage, 0.25);
  EXPECT_DOUBLE_EQ(c[1].scud, 0.2);
  EXPECT_DOUBLE_EQ(c[1].visibility_m, 0.0);  // the type's, when drawn
  // From the west: drifting east.
  EXPECT_NEAR(c[1].wind_mps.x, 10.0, 1e-9);
  EXPECT_NEAR(c[1].wind_mps.y, 0.0, 1e-9);
  EXPECT_TRUE(parse_scenario(with_environment(R"({"clouds": []})")).render.shading.clouds.empty());
}

TEST(EnvironmentScenario, BadCloudLayersNameTheKeyAndTheReason) {
  struct Case {
    std::string environment;
    std::vector<std::string> expect;
  };
  const std::vector<Case> cases = {
      {R"({"clouds": [{"type": "stratus", "coverage_pct": 150, "base_m": 1000}]})",
       {"environment.clouds[0].coverage_pct", "150"}},
      {R"({"clouds": [{"type": "stratus", "base_m": 1000, "thickness_m": -5}]})",
       {"environment.clouds[0].thickness_m"}},
      {R"({"clouds": [{"type": "stratus", "base_m": 200000}]})", {"environment.clouds[0].base_m"}},
      {R"({"clouds": [{"type": "stratus", "base_m": 99900, "thickness_m": 500}]})",
       {"environment.clouds[0].thickness_m", "above 100 km"}},
      {R"({"clouds": [{"type": "fog", "base_m": 100}]})", {"environment.clouds[0].type", "unknown cloud type", "cumulus"}},
      {R"({"clouds": [{"coverage_pct": 50, "base_m": 100}]})", {"environment.clouds[0].type", "missing"}},
      {R"({"clouds": [{"type": "cirrus"}]})", {"environment.clouds[0].base_m", "missing"}},
      {R"({"clouds": [{"type": "cirrus", "base_m": 9000, "colour": 1}]})", {"environment.clouds[0].colour", "unknown key"}},
      {R"({"clouds": [{"type": "stratus", "base_m": 1}, {"type": "stratus", "base_m": 2}, {"type": "stratus", "base_m": 3},
                      {"type": "stratus", "base_m": 4}, {"type": "stratus", "base_m": 5}]})",
       {"environment.clouds", "at most 4"}},
      {R"({"clouds": {"type": "stratus"}})", {"environment.clouds", "must be an array"}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.environment);
    const std::string msg = scenario_error_of(with_environment(c.environment));
    for (const std::string& want : c.expect)
      EXPECT_NE(msg.find(want), std::string::npos) << "message: " << msg << "\nwanted: " << want;
  }
}

}  // namespace
