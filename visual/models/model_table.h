#pragma once
// Which model draws each entity type: the table a simulation host's entity
// types are looked up in, read from JSON (docs/models.md has the schema).
//
//   {
//     "default_box_m": {"x": 4.0, "y": 2.0, "z": 1.5},
//     "entities": [
//       {"type": 1, "name": "light aircraft",
//        "lods": [{"file": "aircraft.glb", "min_size_px": 40},
//                 {"file": "aircraft_coarse.glb", "min_size_px": 0}]}
//     ]
//   }
//
// Files are relative to the table's own folder. Levels go finest first, each
// used while the entity's projected size on screen is at least its
// min_size_px (strictly decreasing). A type the table does not list is drawn
// as a box of default_box_m (body axes: x length, y width, z height).
// Loading the table checks it and that every file exists; the models
// themselves are loaded with load_model (models/model_loader.h).

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace ig::models {

struct LodLevel {
  std::string file;          // the table's folder joined with the file as written
  double min_size_px = 0.0;  // used while the projected size is >= this
};

struct EntityModels {
  std::uint16_t type = 0;     // the host's entity type
  std::string name;
  std::vector<LodLevel> lods;  // finest first; min_size_px strictly decreasing
  // CIGI articulated part id -> the name of the node it moves (optional:
  // "parts": {"1": "rudder"}); a level without that node leaves it still.
  std::map<std::uint8_t, std::string> parts;
};

struct ModelTable {
  std::string source;                           // the JSON file
  glm::vec3 default_box_m{4.0f, 2.0f, 1.5f};    // length, width, height (metres)
  std::vector<EntityModels> entities;           // sorted by type, no type twice

  // The entry for `type`; nullptr when the table has none (draw the box).
  const EntityModels* find(std::uint16_t type) const;
};

// Every failure reads "<file>: \"<key>\": <reason>", the key as a path
// into the JSON (e.g. "entities[1].lods[0].min_size_px").
struct ModelTableError : std::runtime_error {
  explicit ModelTableError(const std::string& message) : std::runtime_error(message) {}
};

// Reads and checks the table; throws ModelTableError.
ModelTable load_model_table(const std::string& path);

// The level to draw an entity whose projected size is `projected_size_px`
// (its bounding sphere's diameter on screen, in pixels): the finest level
// whose min_size_px it reaches. -1 when it is below every level's (too
// small to draw), or the size is not a number.
int choose_lod(const EntityModels& entry, double projected_size_px);

}  // namespace ig::models
