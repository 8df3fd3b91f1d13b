#pragma once
// The rules a cloud layer must meet before it is drawn, and what each cloud
// type looks like (docs/rendering.md, "Clouds"). No GL: the scenario parser,
// the CIGI host's weather and the cloud pass all take layers through here.

#include <optional>
#include <string>

#include "options/cloud_options.h"

namespace ig::environment {

using options::kMaxCloudLayers;  // the most drawn at once
// Nothing above this is weather (the top of a layer may not exceed it).
constexpr double kMaxCloudTopM = 100000.0;

// How a type is built: a deck of uniform thickness broken by coverage
// (stratiform), separate heaps with flat bases and rounded tops whose height
// grows towards their middles (cumuliform), or a thin veil of streaks
// (cirriform).
enum class CloudForm { Stratiform, Cumuliform, Cirriform };

struct CloudLook {
  CloudForm form = CloudForm::Stratiform;
  double element_m = 2000.0;     // typical width of one cloud or gap
  double visibility_m = 100.0;   // inside, unless the layer sets its own
  double streak = 1.0;           // elements this many times longer along the wind (cirrus)
};
CloudLook look_of(options::CloudType type);

// A layer as drawn, or why it is refused: non-finite fields, coverage
// outside [0, 1], a negative thickness, transition band or visibility, scud
// outside [0, 1], a top above kMaxCloudTopM, or a layer entirely below
// `terrain_lowest_m` (the lowest terrain height). A base below the lowest
// terrain is raised to it (the part under the ground is never seen), and
// visibility 0 becomes the type's.
struct CloudLayerCheck {
  std::optional<options::CloudLayer> layer;
  std::string refused;  // empty when accepted
};
CloudLayerCheck check_cloud_layer(options::CloudLayer layer, double terrain_lowest_m);

// The layer's extinction coefficient inside (1/m): Koschmieder's 3.912 / V,
// the contrast threshold of 2 % the fog uses too.
double extinction_per_m(const options::CloudLayer& layer);

}  // namespace ig::environment
