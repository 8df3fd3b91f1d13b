#include "water/water_setup.h"

#include "water/water_detection.h"
#include "water/water_file.h"
#include "water/water_levels.h"

namespace ig::water {

std::shared_ptr<const WaterMap> place_water(terrain::Heightfield& hf, const options::WaterOptions& opts) {
  hf.water.reset();
  std::shared_ptr<WaterMap> map;
  switch (opts.source) {
    case options::WaterSource::Off:
      return nullptr;
    case options::WaterSource::Auto:
      map = std::make_shared<WaterMap>(detect_water(hf));
      break;
    case options::WaterSource::File:
      map = std::make_shared<WaterMap>(read_water_file(hf, opts.file, opts.level_attribute));
      flatten_to_levels(hf, *map);
      break;
  }
  if (!map->empty()) hf.water = map;
  return map;
}

}  // namespace ig::water
