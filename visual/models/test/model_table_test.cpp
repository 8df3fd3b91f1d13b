// The entity type -> model table: read and checked, every mistake named by
// file and key; and the LOD choice.
#include <gtest/gtest.h>

#include <cmath>

#include "models/model_table.h"
#include "models/test/gltf_test_files.h"

namespace {

using namespace ig::models;
using ig::models::test::ModelFilesTest;

class Table : public ModelFilesTest {
 protected:
  void SetUp() override {
    ModelFilesTest::SetUp();
    write("a.glb", "x");  // the table only checks the files exist
    write("a_coarse.glb", "x");
  }
  // `entities` inside a table with a default box; returns the file.
  std::string table(const std::string& entities, const std::string& extra = "") {
    return write("models.json", "{" + extra + "\"entities\": " + entities + "}");
  }
  // Loading `file` fails with "<file>: \"<key>\": <reason...>".
  static void expect_error(const std::string& file, const std::string& key, const std::string& reason) {
    try {
      load_model_table(file);
      ADD_FAILURE() << "no error for " << key;
    } catch (const ModelTableError& e) {
      const std::string want = file + ": \"" + key + "\": " + reason;
      EXPECT_EQ(std::string(e.what()).rfind(want, 0), 0u) << e.what() << "\nexpected to start with: " << want;
    }
  }
};

const char* kGood = R"([
  {"type": 7, "name": "truck", "lods": [{"file": "a.glb", "min_size_px": 30}, {"file": "a_coarse.glb", "min_size_px": 3}]},
  {"type": 2, "name": "car", "lods": [{"file": "a.glb", "min_size_px": 0}]}])";

TEST_F(Table, Reads) {
  const ModelTable t = load_model_table(table(kGood, R"("default_box_m": {"x": 5, "y": 2.5, "z": 2}, )"));
  ASSERT_EQ(t.entities.size(), 2u);
  EXPECT_EQ(t.entities[0].type, 2);  // sorted by type
  const EntityModels* truck = t.find(7);
  ASSERT_NE(truck, nullptr);
  EXPECT_EQ(truck->name, "truck");
  ASSERT_EQ(truck->lods.size(), 2u);
  EXPECT_EQ(truck->lods[1].file, path("a_coarse.glb"));  // relative to the table's folder
  EXPECT_EQ(truck->lods[0].min_size_px, 30.0);
  EXPECT_EQ(t.find(3), nullptr);
  EXPECT_EQ(t.default_box_m, glm::vec3(5.0f, 2.5f, 2.0f));
  // Without a default box: the documented one.
  EXPECT_EQ(load_model_table(table(kGood)).default_box_m, glm::vec3(4.0f, 2.0f, 1.5f));
}

TEST_F(Table, ChooseLod) {
  const ModelTable t = load_model_table(table(kGood));
  const EntityModels& truck = *t.find(7);
  EXPECT_EQ(choose_lod(truck, 500.0), 0);
  EXPECT_EQ(choose_lod(truck, 30.0), 0);   // at the threshold: that level
  EXPECT_EQ(choose_lod(truck, 29.9), 1);
  EXPECT_EQ(choose_lod(truck, 3.0), 1);
  EXPECT_EQ(choose_lod(truck, 2.9), -1);   // below every level: not drawn
  EXPECT_EQ(choose_lod(truck, -1.0), -1);
  EXPECT_EQ(choose_lod(truck, std::nan("")), -1);
  EXPECT_EQ(choose_lod(*t.find(2), 0.0), 0);  // a level from 0 px is always drawn
}

TEST_F(Table, Errors) {
  const std::string lod = R"([{"file": "a.glb", "min_size_px": 0}])";
  expect_error(table(R"({"type": 1})"), "entities", "must be an array");
  expect_error(write("models.json", "{}"), "entities", "missing");
  expect_error(table("[]", R"("colour": 1, )"), "colour", "unknown key (expected one of: default_box_m, entities, comment)");
  expect_error(table(R"([{"name": "x", "lods": )" + lod + "}]"), "entities[0].type", "missing");
  expect_error(table(R"([{"type": 70000, "name": "x", "lods": )" + lod + "}]"), "entities[0].type",
               "must be an integer in 0..65535 (got 70000)");
  expect_error(table(R"([{"type": 1.5, "name": "x", "lods": )" + lod + "}]"), "entities[0].type",
               "must be an integer in 0..65535");
  expect_error(table(R"([{"type": 1, "name": "", "lods": )" + lod + "}]"), "entities[0].name",
               "must be a non-empty string");
  expect_error(table(R"([{"type": 1, "name": "x", "lods": []}])"), "entities[0].lods", "must be a non-empty array");
  expect_error(table(R"([{"type": 1, "name": "x", "lod": )" + lod + "}]"), "entities[0].lod", "unknown key");
  expect_error(table(R"([{"type": 1, "name": "x", "lods": [{"file": "b.glb", "min_size_px": 0}]}])"),
               "entities[0].lods[0].file", "no model file " + path("b.glb"));
  expect_error(table(R"([{"type": 1, "name": "x", "lods": [{"file": "a.glb", "min_size_px": -4}]}])"),
               "entities[0].lods[0].min_size_px", "must be a number in [0, 1e+06] (got -4)");
  expect_error(table(R"([{"type": 1, "name": "x", "lods": [{"file": "a.glb"}]}])"), "entities[0].lods[0].min_size_px",
               "missing");
  expect_error(table(R"([{"type": 1, "name": "x", "lods": [{"file": "a.glb", "min_size_px": 10},
                                                         {"file": "a_coarse.glb", "min_size_px": 10}]}])"),
               "entities[0].lods[1].min_size_px", "must be below the previous level's 10");
  expect_error(table(R"([{"type": 1, "name": "x", "lods": )" + lod + R"(}, {"type": 1, "name": "y", "lods": )" + lod + "}]"),
               "entities[1].type", "type 1 is already listed by entities[0]");
  expect_error(table("[]", R"("default_box_m": {"x": 4, "y": 0, "z": 1}, )"), "default_box_m.y",
               "must be a number in [0.01, 1000] (got 0)");
  expect_error(table("[]", R"("default_box_m": [4, 2, 1], )"), "default_box_m", "must be an object");
  expect_error(table(R"([{"type": 1, "name": "x", "lods": )" + lod + R"(, "parts": {"256": "rudder"}}])"),
               "entities[0].parts.256", "a part id must be an integer in 0..255");
  expect_error(table(R"([{"type": 1, "name": "x", "lods": )" + lod + R"(, "parts": {"one": "rudder"}}])"),
               "entities[0].parts.one", "a part id must be an integer in 0..255");
  expect_error(table(R"([{"type": 1, "name": "x", "lods": )" + lod + R"(, "parts": {"1": ""}}])"),
               "entities[0].parts.1", "must be a non-empty string");
  expect_error(table(R"([{"type": 1, "name": "x", "lods": )" + lod + R"(, "parts": ["rudder"]}])"),
               "entities[0].parts", "must be an object");
}

// Articulated part ids name the nodes they move.
TEST_F(Table, PartsNameTheirNodes) {
  const ModelTable t = load_model_table(table(R"([{"type": 4, "name": "tank", "lods": [{"file": "a.glb", "min_size_px": 0}],
                                                   "parts": {"1": "turret", "12": "gun"}}])"));
  EXPECT_EQ(t.find(4)->parts, (std::map<std::uint8_t, std::string>{{1, "turret"}, {12, "gun"}}));
  EXPECT_TRUE(load_model_table(table(kGood)).find(7)->parts.empty());
}

TEST_F(Table, NotATable) {
  auto message = [](const std::string& file) {
    try {
      load_model_table(file);
    } catch (const ModelTableError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(path("none.json")), path("none.json") + ": cannot be opened (no such file or not readable)");
  const std::string bad = write("bad.json", "{\"entities\": [");
  EXPECT_EQ(message(bad).rfind(bad + ": not valid JSON: parse error", 0), 0u) << message(bad);
  const std::string list = write("list.json", "[]");
  EXPECT_EQ(message(list), list + ": must be a JSON object (got array)");
}

}  // namespace
