// The scenario's "entities": every field read, and every mistake named by
// its key path (docs/scenario.md, "entities").
#include <gtest/gtest.h>

#include <string>

#include "io/scenario.h"
#include "scenario_error.h"

namespace {

using namespace ig::io;

std::string with_entities(const std::string& entities) {
  return R"({"terrain": {"generator": {"size": 257}},
             "path": {"keys": [{"t": 0, "position": [0, 0, 100]}, {"t": 4, "position": [100, 0, 100]}]},
             "entities": )" +
         entities + "}";
}
const std::string kPath = R"({"keys": [{"t": 0, "position": [10, 20, 5], "hpr": [90, 0, 0]}]})";

TEST(ScenarioEntitiesJson, EveryField) {
  const Scenario s = parse_scenario(with_entities(R"([
    {"id": 3, "type": 2, "path": )" + kPath + R"(, "clamp": "conformal", "alpha": 0.5},
    {"id": 4, "type": 1, "path": )" + kPath + R"(, "parent": 3},
    {"id": 5, "type": 7, "path": {"frame": "local", "altitude": "agl", "keys": [{"t": 0, "position": [0, 0, 50]}]}, "parent": 0}
  ])"));
  ASSERT_EQ(s.entities.size(), 3u);
  EXPECT_EQ(s.entities[0].id, 3);
  EXPECT_EQ(s.entities[0].type, 2);
  EXPECT_EQ(s.entities[0].clamp, EntityClamp::Conformal);
  EXPECT_DOUBLE_EQ(s.entities[0].alpha, 0.5);
  EXPECT_EQ(s.entities[0].path.keys.at(0).heading_deg, 90.0);
  EXPECT_EQ(s.entities[1].parent, std::optional<std::uint16_t>(3));
  EXPECT_EQ(s.entities[1].clamp, EntityClamp::None);
  EXPECT_EQ(s.entities[2].parent, std::optional<std::uint16_t>(0));  // the ownship
  EXPECT_TRUE(parse_scenario(with_entities("[]")).entities.empty());
}

TEST(ScenarioEntitiesJson, MistakesNameTheirKey) {
  auto error = [](const std::string& entities) { return scenario_error_of(with_entities(entities)); };
  const std::string p = kPath;
  EXPECT_NE(error(R"({"id": 1})").find("entities: must be an array"), std::string::npos) << error(R"({"id": 1})");
  EXPECT_NE(error(R"([{"id": 0, "type": 1, "path": )" + p + "}]").find("entities[0].id"), std::string::npos);
  EXPECT_NE(error(R"([{"type": 1, "path": )" + p + "}]").find("entities[0].id: required key is missing"),
            std::string::npos);
  EXPECT_NE(error(R"([{"id": 1, "path": )" + p + "}]").find("entities[0].type: required key is missing"),
            std::string::npos);
  EXPECT_NE(error(R"([{"id": 1, "type": 1}])").find("entities[0].path: required key is missing"), std::string::npos);
  const std::string twice = error(R"([{"id": 2, "type": 1, "path": )" + p + R"(}, {"id": 2, "type": 1, "path": )" + p + "}]");
  EXPECT_NE(twice.find("entities[1].id: entity 2 is listed twice"), std::string::npos) << twice;
  const std::string orphan = error(R"([{"id": 2, "type": 1, "path": )" + p + R"(, "parent": 9}])");
  EXPECT_NE(orphan.find("entities[0].parent: entity 9 is not listed"), std::string::npos) << orphan;
  const std::string loop = error(R"([{"id": 2, "type": 1, "path": )" + p + R"(, "parent": 3},
                                     {"id": 3, "type": 1, "path": )" + p + R"(, "parent": 2}])");
  EXPECT_NE(loop.find("an attach loop"), std::string::npos) << loop;
  const std::string clamped = error(R"([{"id": 2, "type": 1, "path": )" + p + R"(, "parent": 0, "clamp": "ground"}])");
  EXPECT_NE(clamped.find("entities[0].clamp: an attached entity is not clamped"), std::string::npos) << clamped;
  EXPECT_NE(error(R"([{"id": 2, "type": 1, "path": )" + p + R"(, "alpha": 1.5}])").find("entities[0].alpha"),
            std::string::npos);
  EXPECT_NE(error(R"([{"id": 2, "type": 1, "path": )" + p + R"(, "clamp": "water"}])").find("entities[0].clamp"),
            std::string::npos);
  EXPECT_NE(error(R"([{"id": 2, "type": 1, "path": {"keys": []}}])").find("entities[0].path.keys"),
            std::string::npos);
  EXPECT_NE(error(R"([{"id": 2, "type": 1, "path": )" + p + R"(, "colour": 1}])").find("colour"), std::string::npos);
}

}  // namespace
