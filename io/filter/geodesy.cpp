#include "io/filter/geodesy.h"

#include <cmath>
#include <numbers>
#include <vector>

#include <GeographicLib/Ellipsoid.hpp>
#include <GeographicLib/Geocentric.hpp>
#include <glm/geometric.hpp>

#include "io/wire/pose_message.h"

namespace ig::io::geo {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// Longitude to (-180, 180]; an in-range one (nearly always: every geodetic
// HAT/HOT and LOS point comes here) is returned as it is.
double wrap_lon(double lon_deg) { return wire::wrap_180(lon_deg); }

}  // namespace

// ECEF, its inverse, the ENU axes and the radii of curvature are
// GeographicLib's (Geocentric, Ellipsoid); this file only adapts the types.

glm::dvec3 geodetic_to_ecef(const Geodetic& g) {
  glm::dvec3 e;
  GeographicLib::Geocentric::WGS84().Forward(g.lat_deg, g.lon_deg, g.height_m, e.x, e.y, e.z);
  return e;
}

Geodetic ecef_to_geodetic(const glm::dvec3& e) {
  Geodetic out;
  GeographicLib::Geocentric::WGS84().Reverse(e.x, e.y, e.z, out.lat_deg, out.lon_deg, out.height_m);
  out.lon_deg = wrap_lon(out.lon_deg);  // GeographicLib's [-180, 180] -> (-180, 180]
  return out;
}

EnuFrame::EnuFrame(const Geodetic& origin) : origin_(origin) {
  // M turns local east-north-up into ECEF: its columns are the axes.
  std::vector<double> m(9);
  GeographicLib::Geocentric::WGS84().Forward(origin.lat_deg, origin.lon_deg, origin.height_m, origin_ecef_.x,
                                             origin_ecef_.y, origin_ecef_.z, m);
  east_ = {m[0], m[3], m[6]};
  north_ = {m[1], m[4], m[7]};
  up_ = {m[2], m[5], m[8]};
}

glm::dvec3 EnuFrame::ecef_dir_to_enu(const glm::dvec3& d) const {
  return {glm::dot(east_, d), glm::dot(north_, d), glm::dot(up_, d)};
}

glm::dvec3 EnuFrame::enu_dir_to_ecef(const glm::dvec3& d) const {
  return east_ * d.x + north_ * d.y + up_ * d.z;
}

glm::dvec3 EnuFrame::ecef_to_enu(const glm::dvec3& ecef) const {
  return ecef_dir_to_enu(ecef - origin_ecef_);
}

glm::dvec3 EnuFrame::enu_to_ecef(const glm::dvec3& enu) const {
  return origin_ecef_ + enu_dir_to_ecef(enu);
}

MetresPerDegree metres_per_degree(double lat_deg) {
  const GeographicLib::Ellipsoid& wgs84 = GeographicLib::Ellipsoid::WGS84();
  return {wgs84.MeridionalCurvatureRadius(lat_deg) * kDeg, wgs84.CircleRadius(lat_deg) * kDeg};
}

std::optional<GeographicGrid> GeographicGrid::make(const std::array<double, 6>& g, double sx,
                                                   double sy) {
  for (double v : g)
    if (!std::isfinite(v)) return std::nullopt;
  if (!(sx > 0.0) || !(sy > 0.0) || !std::isfinite(sx) || !std::isfinite(sy)) return std::nullopt;
  const double det = g[1] * g[5] - g[2] * g[4];
  if (det == 0.0 || !std::isfinite(det)) return std::nullopt;
  GeographicGrid grid;
  grid.g_ = g;
  grid.sx_ = sx;
  grid.sy_ = sy;
  grid.inv00_ = g[5] / det;
  grid.inv01_ = -g[2] / det;
  grid.inv10_ = -g[4] / det;
  grid.inv11_ = g[1] / det;
  grid.ref_lon_ = g[0];
  return grid;
}

glm::dvec2 GeographicGrid::to_index(double lat_deg, double lon_deg) const {
  const double dx = ref_lon_ + wrap_lon(lon_deg - ref_lon_) - g_[0];
  const double dy = lat_deg - g_[3];
  return {inv00_ * dx + inv01_ * dy, inv10_ * dx + inv11_ * dy};
}

glm::dvec2 GeographicGrid::to_local(double lat_deg, double lon_deg) const {
  const glm::dvec2 ij = to_index(lat_deg, lon_deg);
  return {ij.x * sx_, ij.y * sy_};
}

glm::dvec3 GeographicGrid::to_local(const Geodetic& g) const {
  const glm::dvec2 xy = to_local(g.lat_deg, g.lon_deg);
  return {xy.x, xy.y, g.height_m};
}

Geodetic GeographicGrid::from_local(const glm::dvec3& local) const {
  const double i = local.x / sx_, j = local.y / sy_;
  Geodetic out;
  out.lon_deg = wrap_lon(g_[0] + i * g_[1] + j * g_[2]);
  out.lat_deg = g_[3] + i * g_[4] + j * g_[5];
  out.height_m = local.z;
  return out;
}

}  // namespace ig::io::geo
