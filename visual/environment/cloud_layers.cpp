#include "environment/cloud_layers.h"

#include <array>
#include <cmath>
#include <utility>

namespace ig::environment {
namespace {
using options::CloudType;

struct TypeEntry {
  CloudType type;
  CloudLook look;
};

// Element sizes and in-cloud visibilities are typical values of the
// meteorological literature (WMO cloud atlas: cumulus humilis a few hundred
// metres across, altocumulus elements 1-5 deg seen from below; droplet
// clouds 20-100 m visibility inside, ice clouds kilometres).
constexpr std::array<TypeEntry, 10> kTypes{{
    {CloudType::Altocumulus, {CloudForm::Cumuliform, 300.0, 150.0, 1.0}},
    {CloudType::Altostratus, {CloudForm::Stratiform, 3000.0, 150.0, 1.0}},
    {CloudType::Cirrocumulus, {CloudForm::Cumuliform, 200.0, 1500.0, 1.0}},
    {CloudType::Cirrostratus, {CloudForm::Cirriform, 4000.0, 4000.0, 2.0}},
    {CloudType::Cirrus, {CloudForm::Cirriform, 1500.0, 2000.0, 4.0}},
    {CloudType::Cumulonimbus, {CloudForm::Cumuliform, 3000.0, 30.0, 1.0}},
    {CloudType::Cumulus, {CloudForm::Cumuliform, 400.0, 40.0, 1.0}},
    {CloudType::Nimbostratus, {CloudForm::Stratiform, 3000.0, 40.0, 1.0}},
    {CloudType::Stratocumulus, {CloudForm::Cumuliform, 800.0, 60.0, 1.0}},
    {CloudType::Stratus, {CloudForm::Stratiform, 2500.0, 60.0, 1.0}},
}};

const TypeEntry& entry(CloudType t) { return kTypes[std::size_t(t) - 1]; }

bool finite(const options::CloudLayer& l) {
  for (double v : {l.coverage, l.base_m, l.thickness_m, l.transition_m, l.visibility_m, l.scud, l.wind_mps.x,
                   l.wind_mps.y})
    if (!std::isfinite(v)) return false;
  return true;
}
}  // namespace

CloudLook look_of(CloudType type) { return entry(type).look; }

CloudLayerCheck check_cloud_layer(options::CloudLayer l, double terrain_lowest_m) {
  auto refuse = [](std::string why) { return CloudLayerCheck{std::nullopt, std::move(why)}; };
  if (!finite(l)) return refuse("a field is not a finite number");
  if (l.coverage < 0.0 || l.coverage > 1.0) return refuse("coverage outside 0-100 %");
  if (l.thickness_m < 0.0) return refuse("negative thickness");
  if (l.transition_m < 0.0) return refuse("negative transition band");
  if (l.visibility_m < 0.0) return refuse("negative visibility");
  if (l.scud < 0.0 || l.scud > 1.0) return refuse("scud outside 0-100 %");
  const double top = l.base_m + l.thickness_m;
  if (top > kMaxCloudTopM) return refuse("top above 100 km");
  if (std::isfinite(terrain_lowest_m) && top <= terrain_lowest_m) return refuse("entirely below the terrain");
  if (std::isfinite(terrain_lowest_m) && l.base_m < terrain_lowest_m) {
    l.base_m = terrain_lowest_m;
    l.thickness_m = top - terrain_lowest_m;
  }
  if (l.visibility_m == 0.0) l.visibility_m = look_of(l.type).visibility_m;
  return {l, {}};
}

double extinction_per_m(const options::CloudLayer& layer) {
  const double v = layer.visibility_m > 0.0 ? layer.visibility_m : look_of(layer.type).visibility_m;
  return 3.912 / v;
}

}  // namespace ig::environment
