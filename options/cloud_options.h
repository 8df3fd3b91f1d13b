#pragma once
// Cloud layers (docs/rendering.md, "Clouds"): what a scenario's
// environment.clouds and a CIGI host's Weather Control set, and what the
// cloud pass draws. Plain data; the rules a layer must meet and its
// defaults are in visual/environment/cloud_layers.h.

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

namespace ig::options {

// The most cloud layers drawn at once: CIGI's three cloud layers and one
// more (layer ids 10-255 are the IG's own); more are refused.
constexpr int kMaxCloudLayers = 4;

// CIGI 3.3's cloud types, numbered as Weather Control sends them (0 is
// "none": a weather layer without cloud, never a CloudLayer).
enum class CloudType : std::uint8_t {
  Altocumulus = 1,
  Altostratus = 2,
  Cirrocumulus = 3,
  Cirrostratus = 4,
  Cirrus = 5,
  Cumulonimbus = 6,
  Cumulus = 7,
  Nimbostratus = 8,
  Stratocumulus = 9,
  Stratus = 10,
};

// CIGI's names, lower case, in its order (index = value - 1).
inline constexpr std::array<std::string_view, 10> kCloudTypeNames{
    "altocumulus", "altostratus", "cirrocumulus", "cirrostratus", "cirrus",
    "cumulonimbus", "cumulus", "nimbostratus", "stratocumulus", "stratus"};
inline std::string_view cloud_type_name(CloudType t) { return kCloudTypeNames[std::size_t(t) - 1]; }
inline std::optional<CloudType> cloud_type_named(std::string_view name) {
  for (std::size_t i = 0; i < kCloudTypeNames.size(); ++i)
    if (kCloudTypeNames[i] == name) return CloudType(i + 1);
  return std::nullopt;
}
// Weather Control's cloud type field: 1-10 are the types; 0 (none) and
// 11-15 (other) are not.
inline std::optional<CloudType> cloud_type_of_cigi(int value) {
  if (value < 1 || value > int(kCloudTypeNames.size())) return std::nullopt;
  return CloudType(value);
}

struct CloudLayer {
  int id = 1;  // CIGI layer id, or the scenario list's index + 1
  CloudType type = CloudType::Stratus;
  double coverage = 1.0;       // share of the sky it covers seen from below, [0, 1]
  double base_m = 1000.0;      // above mean sea level (the terrain's heights)
  double thickness_m = 300.0;  // base to top
  // Above the top and below the base, the band over which the density (and
  // so the visibility) goes from the layer's to the air's.
  double transition_m = 50.0;
  // Inside the layer; 0: the type's default (environment::default_visibility_m).
  double visibility_m = 0.0;
  double scud = 0.0;         // ragged base: share of the base that hangs lower, [0, 1]
  glm::dvec2 wind_mps{0.0};  // the layer drifts with it (terrain-local x east, y north)
  bool operator==(const CloudLayer&) const = default;
};

using CloudLayers = std::vector<CloudLayer>;

// The velocity of a wind of `speed_mps` blowing from `from_deg` (clockwise
// from north, as weather reports give it): towards the opposite bearing.
inline glm::dvec2 wind_from(double speed_mps, double from_deg) {
  const double to = (from_deg + 180.0) * 3.14159265358979323846 / 180.0;
  return speed_mps * glm::dvec2(std::sin(to), std::cos(to));
}

}  // namespace ig::options
