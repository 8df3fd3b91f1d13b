#include "io/filter/geodesy.h"

#include <cmath>

namespace ig::io::geo {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
constexpr double kEp2 = kWgs84E2 / (1.0 - kWgs84E2);  // second eccentricity squared

double wrap_lon(double lon_deg) {
  double l = std::fmod(lon_deg, 360.0);  // (-360, 360)
  if (l > 180.0) l -= 360.0;
  if (l <= -180.0) l += 360.0;
  return l;
}

}  // namespace

glm::dvec3 geodetic_to_ecef(const Geodetic& g) {
  const double phi = g.lat_deg * kDeg;
  const double lam = g.lon_deg * kDeg;
  const double sp = std::sin(phi), cp = std::cos(phi);
  const double n = kWgs84A / std::sqrt(1.0 - kWgs84E2 * sp * sp);  // prime-vertical radius
  const double r = (n + g.height_m) * cp;
  return {r * std::cos(lam), r * std::sin(lam), (n * (1.0 - kWgs84E2) + g.height_m) * sp};
}

Geodetic ecef_to_geodetic(const glm::dvec3& e) {
  Geodetic out;
  const double p = std::hypot(e.x, e.y);
  out.lon_deg = (p > 0.0) ? std::atan2(e.y, e.x) / kDeg : 0.0;
  // Bowring: iterate on the parametric (reduced) latitude beta. Each step
  // gains about three orders of magnitude near the surface; 4 steps reach
  // double precision for all terrestrial and orbital heights.
  const double a = kWgs84A, b = kWgs84B;
  double beta = std::atan2(e.z * a, p * b);
  double phi = 0.0;
  for (int it = 0; it < 5; ++it) {
    const double sb = std::sin(beta), cb = std::cos(beta);
    phi = std::atan2(e.z + kEp2 * b * sb * sb * sb, p - kWgs84E2 * a * cb * cb * cb);
    const double beta_next = std::atan2((1.0 - kWgs84F) * std::sin(phi), std::cos(phi));
    if (std::fabs(beta_next - beta) < 1e-15) {
      beta = beta_next;
      break;
    }
    beta = beta_next;
  }
  out.lat_deg = phi / kDeg;
  // Height along the normal; well conditioned at all latitudes (no 1/cos).
  const double sp = std::sin(phi), cp = std::cos(phi);
  const double n = a / std::sqrt(1.0 - kWgs84E2 * sp * sp);
  out.height_m = p * cp + e.z * sp - n * (1.0 - kWgs84E2 * sp * sp);
  return out;
}

EnuFrame::EnuFrame(const Geodetic& origin) : origin_(origin) {
  origin_ecef_ = geodetic_to_ecef(origin);
  const double phi = origin.lat_deg * kDeg, lam = origin.lon_deg * kDeg;
  const double sp = std::sin(phi), cp = std::cos(phi), sl = std::sin(lam), cl = std::cos(lam);
  east_ = {-sl, cl, 0.0};
  north_ = {-sp * cl, -sp * sl, cp};
  up_ = {cp * cl, cp * sl, sp};
}

glm::dvec3 EnuFrame::ecef_dir_to_enu(const glm::dvec3& d) const {
  return {east_.x * d.x + east_.y * d.y + east_.z * d.z,
          north_.x * d.x + north_.y * d.y + north_.z * d.z,
          up_.x * d.x + up_.y * d.y + up_.z * d.z};
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
  const double phi = lat_deg * kDeg;
  const double s = std::sin(phi);
  const double w2 = 1.0 - kWgs84E2 * s * s;
  const double meridian = kWgs84A * (1.0 - kWgs84E2) / (w2 * std::sqrt(w2));
  const double prime_vertical = kWgs84A / std::sqrt(w2);
  return {meridian * kDeg, prime_vertical * std::cos(phi) * kDeg};
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
