#include "io/control/register_map.h"

#include <bit>
#include <cmath>
#include <cstring>

namespace ig::io::control {

const char* type_name(RegType t) {
  switch (t) {
    case RegType::U16: return "u16";
    case RegType::U32: return "u32";
    case RegType::F32: return "float32";
  }
  return "?";
}

int block_size(Block b) { return b == Block::Input ? in::kCount : hold::kCount; }

void put_f32(std::uint16_t* r, float v) { put_u32(r, std::bit_cast<std::uint32_t>(v)); }
float get_f32(const std::uint16_t* r) { return std::bit_cast<float>(get_u32(r)); }

void encode_status(const IgStatus& s, std::span<std::uint16_t, in::kCount> r) {
  r[in::kState] = std::uint16_t(s.state);
  r[in::kFlags] = s.flags;
  put_u32(&r[in::kFrameCounter], s.frame_counter);
  put_u32(&r[in::kLastFrameUs], s.last_frame_us);
  put_u32(&r[in::kMedianFrameUs], s.median_frame_us);
  r[in::kLevel1Size] = s.level1_size;
  put_f32(&r[in::kLevel1Ratio], s.level1_ratio);
  put_u32(&r[in::kTriangles], s.triangles);
  put_u32(&r[in::kPoseAgeMs], s.pose_age_ms);
  put_u32(&r[in::kNativeOk], s.native.ok);
  put_u32(&r[in::kNativeBad], s.native.bad);
  put_u32(&r[in::kCigiOk], s.cigi.ok);
  put_u32(&r[in::kCigiBad], s.cigi.bad);
  put_u32(&r[in::kFgfdmOk], s.fgfdm.ok);
  put_u32(&r[in::kFgfdmBad], s.fgfdm.bad);
  put_u32(&r[in::kUptimeS], s.uptime_s);
  r[in::kModbusClients] = s.modbus_clients;
  r[in::kCanLink] = s.can_link;
  put_u32(&r[in::kCanPoses], s.can_poses);
  put_u32(&r[in::kCanRejected], s.can_rejected);
  put_u32(&r[in::kCanErrorFrames], s.can_error_frames);
}

void encode_controls(const IgControls& c, std::span<std::uint16_t, hold::kCount> r) {
  r[hold::kFreeze] = c.freeze ? 1 : 0;
  r[hold::kWireframe] = c.wireframe ? 1 : 0;
  put_f32(&r[hold::kA1], c.a1);
  put_f32(&r[hold::kA2], c.a2);
  put_f32(&r[hold::kAlpha], c.alpha);
  put_u32(&r[hold::kLevel0Budget], c.level0_budget);
  put_f32(&r[hold::kFogVisibility], c.fog_visibility_m);
  r[hold::kCapture] = c.capture ? 1 : 0;
  r[hold::kLatencyMode] = c.latency_mode;
}

IgControls decode_controls(std::span<const std::uint16_t, hold::kCount> r) {
  IgControls c;
  c.freeze = r[hold::kFreeze] != 0;
  c.wireframe = r[hold::kWireframe] != 0;
  c.a1 = get_f32(&r[hold::kA1]);
  c.a2 = get_f32(&r[hold::kA2]);
  c.alpha = get_f32(&r[hold::kAlpha]);
  c.level0_budget = get_u32(&r[hold::kLevel0Budget]);
  c.fog_visibility_m = get_f32(&r[hold::kFogVisibility]);
  c.capture = r[hold::kCapture] != 0;
  c.latency_mode = r[hold::kLatencyMode];
  return c;
}

double register_value(const RegisterDef& d, const std::uint16_t* regs) {
  const std::uint16_t* p = regs + d.address;
  switch (d.type) {
    case RegType::U16: return *p;
    case RegType::U32: return get_u32(p);
    case RegType::F32: return get_f32(p);
  }
  return 0.0;
}

std::optional<std::string> validate_controls(std::span<const std::uint16_t, hold::kCount> r) {
  for (const auto& d : kRegisterMap) {
    if (d.block != Block::Holding) continue;
    const double v = register_value(d, r.data());
    const bool ok = std::isfinite(v) && (d.min_open ? v > d.min : v >= d.min) && (d.max_open ? v < d.max : v <= d.max);
    if (!ok) return std::string(d.name) + " out of range";
  }
  if (options::TwoLevelOptions::check_thresholds(get_f32(&r[hold::kA1]), get_f32(&r[hold::kA2])))
    return std::string("lod_a1 must be below lod_a2");
  return std::nullopt;
}

}  // namespace ig::io::control
