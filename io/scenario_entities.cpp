// The scenario's entities section: scripted traffic (docs/scenario.md).
#include <algorithm>
#include <set>
#include <string>

#include "io/scenario_json.h"

namespace ig::io::scenario_json {

std::vector<EntitySpec> parse_entities(const json& j) {
  const std::string path = "entities";
  require_array(j, path);
  if (j.size() > kMaxScenarioEntities)
    fail(path, "at most " + std::to_string(kMaxScenarioEntities) + " entities (got " + std::to_string(j.size()) + ")");
  std::vector<EntitySpec> out;
  std::set<long long> ids;
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string p = element(path, i);
    const json& e = j[i];
    require_object(e, p);
    check_keys(e, p, {"id", "type", "path", "clamp", "parent", "alpha"});
    EntitySpec s;
    if (!e.contains("id")) fail(child(p, "id"), "required key is missing");
    const long long id = get_integer(e["id"], child(p, "id"), 1, 65535);  // 0 is the ownship
    if (!ids.insert(id).second) fail(child(p, "id"), "entity " + std::to_string(id) + " is listed twice");
    s.id = std::uint16_t(id);
    if (!e.contains("type")) fail(child(p, "type"), "required key is missing");
    s.type = std::uint16_t(get_integer(e["type"], child(p, "type"), 0, 65535));
    if (!e.contains("path")) fail(child(p, "path"), "required key is missing");
    s.path = parse_path(e["path"], child(p, "path"));
    if (e.contains("clamp")) {
      const std::string c = get_choice(e["clamp"], child(p, "clamp"), {"none", "ground", "conformal"});
      s.clamp = c == "none" ? EntityClamp::None : c == "ground" ? EntityClamp::Ground : EntityClamp::Conformal;
    }
    if (e.contains("parent")) s.parent = std::uint16_t(get_integer(e["parent"], child(p, "parent"), 0, 65535));
    if (e.contains("alpha")) s.alpha = get_number_in(e["alpha"], child(p, "alpha"), 0.0, 1.0);
    if (s.parent && s.clamp != EntityClamp::None) fail(child(p, "clamp"), "an attached entity is not clamped");
    out.push_back(s);
  }
  // Parents must be listed (0: the ownship) and reach the ownship or a free
  // entity: no attach loops.
  for (std::size_t i = 0; i < out.size(); ++i) {
    std::set<std::uint16_t> seen{out[i].id};
    for (auto parent = out[i].parent; parent && *parent != 0;) {
      if (!ids.count(*parent))
        fail(child(element(path, i), "parent"), "entity " + std::to_string(*parent) + " is not listed");
      if (!seen.insert(*parent).second)
        fail(child(element(path, i), "parent"), "an attach loop through entity " + std::to_string(*parent));
      const auto it = std::find_if(out.begin(), out.end(), [&](const EntitySpec& e) { return e.id == *parent; });
      parent = it->parent;
    }
  }
  return out;
}

}  // namespace ig::io::scenario_json
