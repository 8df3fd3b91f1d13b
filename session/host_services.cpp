#include "session/host_services.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace ig::session {

using namespace io::wire;

namespace {

constexpr double kDeg = 180.0 / M_PI;

bool is_los(const CigiRequest& r) { return !std::holds_alternative<HatHotRequest>(r); }

std::size_t response_size(const CigiRequest& r) {
  if (const auto* h = std::get_if<HatHotRequest>(&r))
    return h->type == HatHotType::Extended ? kCigiHatHotExtendedResponseSize : kCigiHatHotResponseSize;
  const bool ext = std::visit(
      [](const auto& q) {
        if constexpr (std::is_same_v<std::decay_t<decltype(q)>, HatHotRequest>) return false;
        else return q.extended;
      },
      r);
  return ext ? kCigiLosExtendedResponseSize : kCigiLosResponseSize;
}

// Azimuth from north (clockwise) and elevation from the horizon of a unit
// vector in local ENU, degrees, as CIGI gives surface normals.
void azimuth_elevation(const glm::dvec3& n, float& az, float& el) {
  az = float(std::atan2(n.x, n.y) * kDeg);
  el = float(std::asin(std::clamp(n.z, -1.0, 1.0)) * kDeg);
}

// CIGI entity body axes (x forward, y right, z down) in local ENU.
struct BodyAxes {
  glm::dvec3 forward, right, down;
};
BodyAxes body_axes(const io::Pose& p) {
  return {io::forward_of(p.attitude), io::right_of(p.attitude), -io::up_of(p.attitude)};
}

// A LOS answer starts as an invalid one that names its request and frame.
template <class LosRequest>
LosResponse los_response_for(const LosRequest& r, std::uint32_t host_frame) {
  LosResponse out;
  out.id = r.id;
  out.extended = r.extended;
  out.host_frame = host_frame;
  return out;
}

}  // namespace

HostServices::HostServices(const terrain::Heightfield& hf, double earth_radius_m, io::GeodeticToLocal to_local,
                           LocalToGeodetic to_geodetic, HostServicesOptions options,
                           const terrain::HeightPyramid* pyramid)
    : query_(pyramid ? terrain::TerrainQuery(hf, *pyramid, earth_radius_m) : terrain::TerrainQuery(hf, earth_radius_m)),
      to_local_(std::move(to_local)),
      to_geodetic_(std::move(to_geodetic)),
      options_(options) {}

void HostServices::take(std::span<const std::uint8_t> datagram) { take(decode_cigi_requests(datagram)); }

void HostServices::take(const CigiRequests& r) {
  if (!r.host_frame) return;  // not a host datagram: the pose intake counts it
  host_frame_ = *r.host_frame;
  for (QueryReject why : r.rejects) drop(query_reject_name(why));
  if (r.overflow) counters_.dropped["too-many-in-datagram"] += r.overflow;
  for (const CigiRequest& q : r.requests) {
    ++counters_.requests;
    const auto key = std::make_pair(kind(q), request_id(q));
    const std::uint8_t period = update_period(q);
    if (period > 0) {
      if (!periodic_.count(key) && periodic_.size() >= options_.max_periodic) {
        drop("too-many-periodic");
        continue;
      }
      periodic_[key] = Periodic{q, frame_};  // first answer in this frame, then every period-th
      continue;
    }
    if (periodic_.erase(key)) ++counters_.cancelled;  // the same id with period 0 ends it
    if (queue_.size() >= options_.max_pending) {
      drop("queue-full");
      continue;
    }
    queue_.push_back(Pending{q, frame_});
  }
}

std::vector<CigiResponse> HostServices::answer_frame(const io::Pose& ownship) {
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<CigiResponse> out;
  out.reserve(std::min(queue_.size() + periodic_.size(), options_.max_hat_hot_per_frame + options_.max_los_per_frame));
  std::size_t hat_hot = 0, los = 0, bytes = kCigiStartOfFrameSize;
  auto fits = [&](const CigiRequest& q) {
    if (is_los(q) ? los >= options_.max_los_per_frame : hat_hot >= options_.max_hat_hot_per_frame) return false;
    return bytes + response_size(q) <= options_.max_datagram_bytes;
  };
  auto spend = [&](const CigiRequest& q) {
    ++(is_los(q) ? los : hat_hot);
    bytes += response_size(q);
    out.push_back(answer(q, ownship));
  };
  // HAT/HOT points are scattered over a DEM the renderer has just pushed out
  // of the caches: start fetching the samples of those about to be answered
  // (geodetic ones; entity offsets are placed from the pose below).
  std::size_t ahead = 0;
  for (auto it = queue_.begin(); it != queue_.end() && ahead < options_.max_hat_hot_per_frame; ++it) {
    const auto* h = std::get_if<HatHotRequest>(&it->request);
    if (!h || h->coords != CigiCoords::Geodetic || !to_local_) continue;
    ++ahead;
    if (const auto p = to_local_(h->point.x, h->point.y, h->point.z)) query_.prefetch(p->x, p->y);
  }
  for (auto& [key, p] : periodic_) {
    if (p.next_frame > frame_ || !fits(p.request)) continue;  // not due, or due again next frame
    spend(p.request);
    ++counters_.periodic_answers;
    p.next_frame = frame_ + update_period(p.request);
  }
  while (!queue_.empty() && fits(queue_.front().request)) {
    if (queue_.front().frame < frame_) ++counters_.deferred;
    spend(queue_.front().request);
    queue_.pop_front();
  }
  ++frame_;
  native_hat_hot_ = native_los_ = 0;
  last_frame_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (!out.empty()) {
    ++frames_with_work_;
    sum_frame_ms_ += last_frame_ms_;
    max_frame_ms_ = std::max(max_frame_ms_, last_frame_ms_);
  }
  return out;
}

std::vector<std::uint8_t> HostServices::frame_datagram(const std::array<std::uint8_t, kCigiStartOfFrameSize>& sof,
                                                       const io::Pose& ownship) {
  std::vector<std::uint8_t> d(sof.begin(), sof.end());
  for (const CigiResponse& r : answer_frame(ownship)) append_cigi_response(r, false, d);
  return d;
}

CigiResponse HostServices::answer(const CigiRequest& request, const io::Pose& ownship) {
  ++counters_.answered;
  ++(std::holds_alternative<HatHotRequest>(request) ? counters_.answered_hat_hot : counters_.answered_los);
  CigiResponse r = respond(request, ownship);
  const bool valid = std::visit([](const auto& a) { return a.valid; }, r);
  if (!valid) ++counters_.invalid;
  return r;
}

CigiResponse HostServices::cast_collision_segment(const LosSegmentRequest& segment, const io::Pose& ownship) {
  ++counters_.collision_casts;
  return respond(segment, ownship);
}

CigiResponse HostServices::respond(const CigiRequest& request, const io::Pose& ownship) {
  // Entity-relative points are relative to the request's entity: the ownship,
  // or one the entity lookup places (an unknown one: no reference pose).
  const std::uint16_t entity = std::visit([](const auto& q) { return q.entity; }, request);
  std::optional<io::Pose> other;
  if (entity != kCigiOwnshipEntity && entity_lookup_) other = entity_lookup_(entity);
  const io::Pose& reference = other ? *other : ownship;
  const bool known = entity == kCigiOwnshipEntity || other.has_value();
  return std::visit(
      [&](const auto& q) -> CigiResponse {
        using T = std::decay_t<decltype(q)>;
        if constexpr (std::is_same_v<T, HatHotRequest>) return hat_hot(q, reference, known);
        else if constexpr (std::is_same_v<T, LosSegmentRequest>) return los_segment(q, reference, known, ownship);
        else return los_vector(q, reference, known);
      },
      request);
}

std::optional<std::array<std::uint8_t, kNativeQuerySize>> HostServices::answer_native(
    std::span<const std::uint8_t> datagram) {
  const NativeQueryResult r = decode_native_query(datagram);
  if (!r.query) {
    drop(std::string("native-") + native_query_reject_name(*r.reject));
    return std::nullopt;
  }
  ++counters_.requests;
  const bool los = r.query->kind != NativeQueryKind::Height;
  std::size_t& spent = los ? native_los_ : native_hat_hot_;
  if (spent >= (los ? options_.max_los_per_frame : options_.max_hat_hot_per_frame)) {
    drop("native-over-budget");  // no queue for native queries: the host asks again
    return std::nullopt;
  }
  ++spent;
  ++counters_.answered;
  ++counters_.native_answered;
  const NativeAnswer a = answer(*r.query);
  if (!a.valid) ++counters_.invalid;
  return encode_native_answer(a);
}

NativeAnswer HostServices::answer(const NativeQuery& q) {
  NativeAnswer out;
  out.kind = q.kind;
  out.geodetic = q.geodetic;
  out.id = q.id;
  out.ig_frame = std::uint32_t(frame_);
  auto to_local = [&](const glm::dvec3& p) -> std::optional<glm::dvec3> {
    if (!q.geodetic) return p;
    return to_local_ ? to_local_(p.x, p.y, p.z) : std::nullopt;
  };
  auto back = [&](const glm::dvec3& p) -> std::optional<glm::dvec3> {
    if (!q.geodetic) return p;
    return to_geodetic_ ? to_geodetic_(p) : std::nullopt;
  };
  const auto a = to_local(q.a);
  if (!a || !query_.inside(a->x, a->y)) return out;
  if (q.kind == NativeQueryKind::Height) {
    const auto s = surface_for_hot(a->x, a->y);
    const auto p = back(glm::dvec3(a->x, a->y, s->height_m));
    if (!p) return out;
    out.valid = true;
    out.hot_or_range_m = s->height_m;
    out.hat_m = a->z - s->height_m;
    out.point = *p;
    out.normal = s->normal;
    out.material = std::uint32_t(s->material);
    return out;
  }
  std::optional<terrain::LosHit> hit;
  if (q.kind == NativeQueryKind::LosSegment) {
    const auto b = to_local(q.b);
    if (!b) return out;
    hit = query_.segment(*a, *b);
  } else {
    hit = query_.ray(*a, q.b, q.min_range_m, q.max_range_m);
  }
  out.valid = true;
  if (!hit) return out;
  const auto p = back(hit->point);
  if (!p) {
    out.valid = false;
    return out;
  }
  out.hit = true;
  out.hot_or_range_m = hit->range_m;
  out.point = *p;
  out.normal = hit->normal;
  out.material = std::uint32_t(hit->material);
  return out;
}

std::optional<terrain::SurfacePoint> HostServices::surface_for_hot(double x_m, double y_m) const {
  auto s = query_.surface_at(x_m, y_m);
  // Water is answered at its level however the ground under it is drawn.
  if (!s || !drawn_height_ || s->material == terrain::SurfaceMaterial::Water) return s;
  const auto h = drawn_height_(x_m, y_m);
  if (!h) return s;  // full resolution drawn there
  // The drawn (Level0) triangle's slope from its heights half a metre around.
  const double e = 0.5;
  const auto hx0 = drawn_height_(x_m - e, y_m), hx1 = drawn_height_(x_m + e, y_m);
  const auto hy0 = drawn_height_(x_m, y_m - e), hy1 = drawn_height_(x_m, y_m + e);
  if (hx0 && hx1 && hy0 && hy1)
    s->normal = glm::normalize(glm::dvec3(-(*hx1 - *hx0) / (2 * e), -(*hy1 - *hy0) / (2 * e), 1.0));
  s->height_m = *h;
  return s;
}

std::optional<glm::dvec3> HostServices::place(const glm::dvec3& p, CigiCoords c, bool entity_known,
                                               const io::Pose& entity) {
  if (c == CigiCoords::Geodetic) return to_local_ ? to_local_(p.x, p.y, p.z) : std::nullopt;
  if (!entity_known) return std::nullopt;  // an entity this IG does not have
  const BodyAxes b = body_axes(entity);
  return entity.position + p.x * b.forward + p.y * b.right + p.z * b.down;
}

HatHotResponse HostServices::hat_hot(const HatHotRequest& r, const io::Pose& ownship, bool entity_known) {
  HatHotResponse out;
  out.id = r.id;
  out.extended = r.type == HatHotType::Extended;
  out.type = r.type;
  out.host_frame = host_frame_;
  const auto p = place(r.point, r.coords, entity_known, ownship);
  const auto s = p ? surface_for_hot(p->x, p->y) : std::nullopt;
  if (!s) return out;  // outside the terrain (or an unknown entity): valid clear
  out.valid = true;
  out.hot_m = s->height_m;
  out.hat_m = p->z - s->height_m;
  // Only the extended response carries the material and the normal (two
  // inverse trig calls).
  if (!out.extended) return out;
  out.material = std::uint32_t(s->material);
  azimuth_elevation(s->normal, out.normal_azimuth_deg, out.normal_elevation_deg);
  return out;
}

void HostServices::fill_hit(LosResponse& out, const std::optional<terrain::LosHit>& hit, CigiCoords coords,
                            const io::Pose& ownship) {
  out.visible = !hit;
  out.range_valid = hit.has_value();
  if (!hit) return;
  out.range_m = hit->range_m;
  out.material = std::uint32_t(hit->material);  // collision notifications carry it too
  if (!out.extended) return;  // the basic response carries the range only
  azimuth_elevation(hit->normal, out.normal_azimuth_deg, out.normal_elevation_deg);
  if (coords == CigiCoords::Entity) {
    const BodyAxes b = body_axes(ownship);
    const glm::dvec3 d = hit->point - ownship.position;
    out.point = {glm::dot(d, b.forward), glm::dot(d, b.right), glm::dot(d, b.down)};
  } else if (const auto g = to_geodetic_ ? to_geodetic_(hit->point) : std::nullopt) {
    out.point = *g;
  } else {
    out.valid = false;  // a projected DEM: no way back to latitude / longitude here
  }
}

LosResponse HostServices::los_segment(const LosSegmentRequest& r, const io::Pose& reference, bool entity_known,
                                      const io::Pose& ownship) {
  LosResponse out = los_response_for(r, host_frame_);
  const auto from = place(r.source, r.source_coords, entity_known, reference);
  // The destination may be relative to another entity (the ownship or one the lookup places).
  std::optional<io::Pose> other;
  if (r.destination_entity_valid && r.destination_entity != r.entity)
    other = r.destination_entity == kCigiOwnshipEntity ? std::optional(ownship)
            : entity_lookup_                            ? entity_lookup_(r.destination_entity)
                                                        : std::nullopt;
  const bool other_entity = r.destination_entity_valid && r.destination_entity != r.entity;
  const auto to = place(r.destination, r.destination_coords, other_entity ? other.has_value() : entity_known,
                        other ? *other : reference);
  if (!from || !to || !query_.inside(from->x, from->y)) return out;
  out.valid = true;
  fill_hit(out, query_.segment(*from, *to), r.response_coords, reference);
  return out;
}

LosResponse HostServices::los_vector(const LosVectorRequest& r, const io::Pose& ownship, bool entity_known) {
  LosResponse out = los_response_for(r, host_frame_);
  const auto from = place(r.source, r.source_coords, entity_known, ownship);
  if (!from || !query_.inside(from->x, from->y)) return out;
  const double az = r.azimuth_deg / kDeg, el = r.elevation_deg / kDeg;
  glm::dvec3 dir;
  if (r.source_coords == CigiCoords::Geodetic) {
    dir = {std::cos(el) * std::sin(az), std::cos(el) * std::cos(az), std::sin(el)};
  } else {  // from the entity's x axis, elevation up from its x-y plane
    const BodyAxes b = body_axes(ownship);
    dir = std::cos(el) * std::cos(az) * b.forward + std::cos(el) * std::sin(az) * b.right - std::sin(el) * b.down;
  }
  out.valid = true;
  fill_hit(out, query_.ray(*from, dir, r.min_range_m, r.max_range_m), r.response_coords, ownship);
  return out;
}

nlohmann::json HostServices::summary() const {
  return {{"requests", counters_.requests},
          {"answered", counters_.answered},
          {"invalid", counters_.invalid},
          {"deferred", counters_.deferred},
          {"periodic_answers", counters_.periodic_answers},
          {"cancelled", counters_.cancelled},
          {"native_answered", counters_.native_answered},
          {"answered_hat_hot", counters_.answered_hat_hot},
          {"answered_los", counters_.answered_los},
          {"collision_casts", counters_.collision_casts},
          {"dropped", counters_.dropped},
          {"pending", queue_.size()},
          {"periodic", periodic_.size()},
          {"frames_with_answers", frames_with_work_},
          {"answer_ms_mean", frames_with_work_ ? sum_frame_ms_ / double(frames_with_work_) : 0.0},
          {"answer_ms_max", max_frame_ms_}};
}

}  // namespace ig::session
