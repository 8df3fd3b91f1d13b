// The CIGI host-services load: one host datagram a frame with HAT/HOT and
// line-of-sight requests over a DEM. Shared by the in-process benchmark
// (tools/bench/bench_host_services.cpp) and the loopback test host
// (tests/tools/cigi_query_host.cpp --bench) so both send the same load
// (docs/results.md, host services).
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include <glm/vec3.hpp>

#include "io/filter/geodesy.h"
#include "io/wire/pose_message.h"
#include "terrain/heightfield.h"

namespace ig::load {

struct RequestLoad {
  int hot = 1000;        // HAT/HOT requests a frame: a third each HAT, HOT, extended
  int los = 100;         // extended LOS requests a frame: half segments, half vectors
  double spread_m = 0.0; // HAT/HOT points within this of the ownship; 0: the whole DEM
  double los_spread_m = 0.0;  // LOS sources within this of the ownship; 0: the whole DEM
};

// Requests drawn from one seeded generator, so a run is repeatable: HAT/HOT
// points 3000 m high over the middle 90% of the DEM (or near the ownship);
// LOS from 2000 m above the terrain (over the same 90%, or near the
// ownship), 5-20 km long, segments ending on the surface, vectors 5-30
// degrees down. Needs a geographic DEM (throws
// std::runtime_error otherwise): requests are in geodetic coordinates.
class CigiRequestMix {
 public:
  explicit CigiRequestMix(const terrain::Heightfield& hf, std::uint64_t seed = 15);

  // Where the ownship flies (terrain-local metres): the middle in x, 40% in y, 4000 m.
  glm::dvec3 ownship_at() const;
  // Terrain-local metres -> (lat deg, lon deg, height m).
  glm::dvec3 geodetic(const glm::dvec3& local) const;

  // Host frame `frame`: IG Control (operate) with `ownship` as its Entity
  // Control, then the requests (ids from 0). Odd frames are written in the
  // byte order opposite to this machine's.
  std::vector<std::uint8_t> datagram(std::uint32_t frame, const RequestLoad& load, const io::wire::PoseMessage& ownship);
  // The same around `around` (terrain-local metres) instead of ownship_at():
  // a host whose ownship moves asks about the terrain near it. Points are
  // kept on the DEM.
  std::vector<std::uint8_t> datagram(std::uint32_t frame, const RequestLoad& load, const io::wire::PoseMessage& ownship,
                                     const glm::dvec3& around);

 private:
  const terrain::Heightfield& hf_;
  io::geo::GeographicGrid grid_;
  std::mt19937_64 rng_;
  std::uniform_real_distribution<double> ux_, uy_;
};

}  // namespace ig::load
