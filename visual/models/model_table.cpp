#include "models/model_table.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>

#include <nlohmann/json.hpp>

namespace ig::models {

namespace {

using json = nlohmann::json;

// Checks and reads one table; every failure names the file and the key.
class TableReader {
 public:
  explicit TableReader(std::string path) : path_(std::move(path)) {}

  [[noreturn]] void fail(const std::string& key, const std::string& reason) const {
    throw ModelTableError(path_ + ": \"" + key + "\": " + reason);
  }

  static std::string got(const json& j) {
    std::string s = j.dump();
    if (s.size() > 40) s = s.substr(0, 37) + "...";
    return " (got " + s + ")";
  }

  void require_object(const json& j, const std::string& key) const {
    if (!j.is_object()) fail(key, "must be an object" + got(j));
  }

  // Every key of `j` must be one of `allowed`.
  void only_keys(const json& j, const std::string& key, std::initializer_list<const char*> allowed) const {
    for (auto it = j.begin(); it != j.end(); ++it) {
      const bool known = std::any_of(allowed.begin(), allowed.end(), [&](const char* a) { return it.key() == a; });
      if (known) continue;
      std::string list;
      for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
      fail(join(key, it.key()), "unknown key (expected one of: " + list + ")");
    }
  }

  const json& member(const json& j, const std::string& key, const char* name) const {
    const auto it = j.find(name);
    if (it == j.end()) fail(join(key, name), "missing");
    return *it;
  }

  double number(const json& j, const std::string& key, double lo, double hi) const {
    if (!j.is_number() || !std::isfinite(j.get<double>()) || j.get<double>() < lo || j.get<double>() > hi) {
      std::ostringstream range;
      range << "must be a number in [" << lo << ", " << hi << "]";
      fail(key, range.str() + got(j));
    }
    return j.get<double>();
  }

  std::string text(const json& j, const std::string& key) const {
    if (!j.is_string() || j.get<std::string>().empty()) fail(key, "must be a non-empty string" + got(j));
    return j.get<std::string>();
  }

  static std::string join(const std::string& key, const std::string& child) {
    return key.empty() ? child : key + "." + child;
  }
  static std::string at(const std::string& key, std::size_t i) { return key + "[" + std::to_string(i) + "]"; }

  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

LodLevel read_level(const TableReader& r, const json& j, const std::string& key, const std::filesystem::path& dir) {
  r.require_object(j, key);
  r.only_keys(j, key, {"file", "min_size_px"});
  LodLevel level;
  const std::string file = r.text(r.member(j, key, "file"), TableReader::join(key, "file"));
  const std::filesystem::path full = dir / file;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(full, ec)) {
    r.fail(TableReader::join(key, "file"), "no model file " + full.string());
  }
  level.file = full.string();
  level.min_size_px = r.number(r.member(j, key, "min_size_px"), TableReader::join(key, "min_size_px"), 0.0, 1e6);
  return level;
}

EntityModels read_entity(const TableReader& r, const json& j, const std::string& key,
                         const std::filesystem::path& dir) {
  r.require_object(j, key);
  r.only_keys(j, key, {"type", "name", "lods", "parts", "comment"});
  EntityModels e;
  const json& type = r.member(j, key, "type");
  if (!type.is_number_integer() || type.get<long long>() < 0 || type.get<long long>() > 65535) {
    r.fail(TableReader::join(key, "type"), "must be an integer in 0..65535" + TableReader::got(type));
  }
  e.type = std::uint16_t(type.get<long long>());
  e.name = r.text(r.member(j, key, "name"), TableReader::join(key, "name"));
  const std::string lods_key = TableReader::join(key, "lods");
  const json& lods = r.member(j, key, "lods");
  if (!lods.is_array() || lods.empty()) r.fail(lods_key, "must be a non-empty array of levels" + TableReader::got(lods));
  for (std::size_t i = 0; i < lods.size(); ++i) {
    LodLevel level = read_level(r, lods[i], TableReader::at(lods_key, i), dir);
    if (!e.lods.empty() && !(level.min_size_px < e.lods.back().min_size_px)) {
      std::ostringstream why;
      why << "must be below the previous level's " << e.lods.back().min_size_px
          << " (levels go finest first, min_size_px strictly decreasing)" << TableReader::got(lods[i]["min_size_px"]);
      r.fail(TableReader::join(TableReader::at(lods_key, i), "min_size_px"), why.str());
    }
    e.lods.push_back(std::move(level));
  }
  if (j.contains("parts")) {
    // CIGI articulated part id -> the node it moves, by name.
    const std::string parts_key = TableReader::join(key, "parts");
    r.require_object(j["parts"], parts_key);
    for (auto it = j["parts"].begin(); it != j["parts"].end(); ++it) {
      const std::string part_key = TableReader::join(parts_key, it.key());
      const std::string& id = it.key();
      if (id.empty() || id.size() > 3 || !std::all_of(id.begin(), id.end(), [](char c) { return c >= '0' && c <= '9'; }) ||
          std::stoi(id) > 255)
        r.fail(part_key, "a part id must be an integer in 0..255");
      e.parts[std::uint8_t(std::stoi(id))] = r.text(it.value(), part_key);
    }
  }
  return e;
}

}  // namespace

const EntityModels* ModelTable::find(std::uint16_t type) const {
  const auto it = std::lower_bound(entities.begin(), entities.end(), type,
                                   [](const EntityModels& e, std::uint16_t t) { return e.type < t; });
  return it != entities.end() && it->type == type ? &*it : nullptr;
}

ModelTable load_model_table(const std::string& path) {
  const TableReader r(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ModelTableError(path + ": cannot be opened (no such file or not readable)");
  json doc;
  try {
    doc = json::parse(in);
  } catch (const json::exception& e) {
    std::string what = e.what();
    const auto close = what.find("] ");
    if (!what.empty() && what[0] == '[' && close != std::string::npos) what.erase(0, close + 2);
    throw ModelTableError(path + ": not valid JSON: " + what);
  }
  if (!doc.is_object()) throw ModelTableError(path + ": must be a JSON object (got " + doc.type_name() + ")");
  r.only_keys(doc, "", {"default_box_m", "entities", "comment"});

  ModelTable table;
  table.source = path;
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  if (const auto box = doc.find("default_box_m"); box != doc.end()) {
    r.require_object(*box, "default_box_m");
    r.only_keys(*box, "default_box_m", {"x", "y", "z"});
    for (int k = 0; k < 3; ++k) {
      const char* axis = k == 0 ? "x" : k == 1 ? "y" : "z";
      const std::string key = std::string("default_box_m.") + axis;
      table.default_box_m[k] = float(r.number(r.member(*box, "default_box_m", axis), key, 0.01, 1000.0));
    }
  }
  const json& entities = r.member(doc, "", "entities");
  if (!entities.is_array()) r.fail("entities", "must be an array" + TableReader::got(entities));
  for (std::size_t i = 0; i < entities.size(); ++i) {
    const std::string key = TableReader::at("entities", i);
    EntityModels e = read_entity(r, entities[i], key, dir);
    for (std::size_t k = 0; k < table.entities.size(); ++k) {
      if (table.entities[k].type == e.type) {
        r.fail(key + ".type", "type " + std::to_string(e.type) + " is already listed by entities[" +
                                  std::to_string(k) + "]");
      }
    }
    table.entities.push_back(std::move(e));
  }
  std::sort(table.entities.begin(), table.entities.end(),
            [](const EntityModels& a, const EntityModels& b) { return a.type < b.type; });
  return table;
}

int choose_lod(const EntityModels& entry, double projected_size_px) {
  if (!(projected_size_px >= 0.0)) return -1;  // NaN or negative
  for (std::size_t i = 0; i < entry.lods.size(); ++i) {
    if (projected_size_px >= entry.lods[i].min_size_px) return int(i);
  }
  return -1;
}

}  // namespace ig::models
