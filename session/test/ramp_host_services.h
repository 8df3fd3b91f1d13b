#pragma once
// Host services on the ramp terrain (terrain/test/ramp_terrain.h), for the
// tests of what a host asks of the IG.

#include <glm/vec3.hpp>

#include "session/host_services.h"
#include "session/scene_setup.h"
#include "terrain/test/ramp_terrain.h"

namespace ig::session::test {

struct RampHostServices {
  terrain::Heightfield hf = terrain::test::make_ramp_terrain();
  HostServices services;
  explicit RampHostServices(HostServicesOptions o = {})
      : services(hf, 0.0, geodetic_placer(hf), local_to_geodetic(hf), o) {}
  // Terrain-local metres -> latitude, longitude, altitude.
  glm::dvec3 geodetic(double x, double y, double z) const { return *local_to_geodetic(hf)(glm::dvec3(x, y, z)); }
};

}  // namespace ig::session::test
