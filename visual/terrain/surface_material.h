#pragma once
// What the surface is at a point, as the host queries report it: the
// material code of CIGI's HAT/HOT Extended Response, LOS Extended Response
// and Collision Detection Segment Notification, and of the native answer
// (docs/host-services.md, "Materials"). The values go on the wire.

#include <cstdint>

namespace ig::terrain {

enum class SurfaceMaterial : std::uint32_t {
  Land = 0,   // terrain (what every answer said before water)
  Water = 1,  // the sea or a lake (terrain.water)
};

}  // namespace ig::terrain
