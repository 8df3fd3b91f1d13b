#include "cigi_request_mix.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "io/wire/cigi.h"
#include "io/wire/cigi_queries.h"

namespace ig::load {

namespace {

using glm::dvec3;
using namespace ig::io::wire;

io::geo::GeographicGrid grid_of(const terrain::Heightfield& hf) {
  std::optional<io::geo::GeographicGrid> grid;
  if (hf.georef && hf.georef->geographic)
    grid = io::geo::GeographicGrid::make(hf.georef->grid_to_crs, hf.spacing_x_m, hf.spacing_y_m);
  if (!grid) throw std::runtime_error("CIGI requests need a DEM in geographic coordinates");
  return *grid;
}

}  // namespace

CigiRequestMix::CigiRequestMix(const terrain::Heightfield& hf, std::uint64_t seed)
    : hf_(hf),
      grid_(grid_of(hf)),
      rng_(seed),
      ux_(0.05 * hf.extent_x_m(), 0.95 * hf.extent_x_m()),
      uy_(0.05 * hf.extent_y_m(), 0.95 * hf.extent_y_m()) {}

dvec3 CigiRequestMix::ownship_at() const { return {0.5 * hf_.extent_x_m(), 0.4 * hf_.extent_y_m(), 4000.0}; }

dvec3 CigiRequestMix::geodetic(const dvec3& local) const {
  const io::geo::Geodetic g = grid_.from_local(local);
  return {g.lat_deg, g.lon_deg, g.height_m};
}

std::vector<std::uint8_t> CigiRequestMix::datagram(std::uint32_t frame, const RequestLoad& load,
                                                   const PoseMessage& ownship) {
  return datagram(frame, load, ownship, ownship_at());
}

std::vector<std::uint8_t> CigiRequestMix::datagram(std::uint32_t frame, const RequestLoad& load,
                                                   const PoseMessage& ownship, const dvec3& own) {
  const bool swap = frame % 2 == 1;
  std::vector<std::uint8_t> d = encode_cigi_host_datagram(frame, kCigiModeOperate, ownship, swap);
  auto add = [&](const auto& packet) { d.insert(d.end(), packet.begin(), packet.end()); };
  std::uniform_real_distribution<double> near(-load.spread_m, load.spread_m), uaz(-180.0, 180.0),
      los_near(-load.los_spread_m, load.los_spread_m);
  auto on_dem_x = [&](double x) { return std::clamp(x, 0.0, hf_.extent_x_m()); };
  auto on_dem_y = [&](double y) { return std::clamp(y, 0.0, hf_.extent_y_m()); };
  for (int n = 0; n < load.hot; ++n) {
    HatHotRequest r;
    r.id = std::uint16_t(n);
    r.type = HatHotType(n % 3);
    if (load.spread_m > 0) {
      const double x = on_dem_x(own.x + near(rng_)), y = on_dem_y(own.y + near(rng_));
      r.point = geodetic(dvec3(x, y, 3000.0));
    } else {
      const double x = ux_(rng_), y = uy_(rng_);
      r.point = geodetic(dvec3(x, y, 3000.0));
    }
    add(encode_cigi_hat_hot_request(r, swap));
  }
  for (int n = 0; n < load.los; ++n) {
    double x, y;
    if (load.los_spread_m > 0) {
      x = on_dem_x(own.x + los_near(rng_));
      y = on_dem_y(own.y + los_near(rng_));
    } else {
      x = ux_(rng_);
      y = uy_(rng_);
    }
    const double az = uaz(rng_) * M_PI / 180, dist = 5000.0 + 15000.0 * (n % 7) / 6.0;
    const dvec3 from(x, y, hf_.sample_surface(x, y) + 2000.0);
    if (n % 2 == 0) {
      LosSegmentRequest r;
      r.id = std::uint16_t(n);
      r.extended = true;
      r.source = geodetic(from);
      dvec3 to = from + dist * dvec3(std::sin(az), std::cos(az), 0.0);
      to.x = on_dem_x(to.x);
      to.y = on_dem_y(to.y);
      to.z = hf_.sample_surface(to.x, to.y);
      r.destination = geodetic(to);
      add(encode_cigi_los_segment_request(r, swap));
    } else {
      LosVectorRequest r;
      r.id = std::uint16_t(n);
      r.extended = true;
      r.source = geodetic(from);
      r.azimuth_deg = float(az * 180 / M_PI);
      r.elevation_deg = float(-5.0 - 25.0 * (n % 5) / 4.0);
      r.max_range_m = float(dist);
      add(encode_cigi_los_vector_request(r, swap));
    }
  }
  return d;
}

}  // namespace ig::load
