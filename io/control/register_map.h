#pragma once
// The Modbus register map of ig serve: one table (kRegisterMap) with every
// register's block, address, type, units and range. The server encodes and
// validates with it; the docs (docs/modbus.md) and tests are checked against
// it. Addresses are 0-based protocol addresses (mbpoll: use -0, or add 1).
//
// 32-bit values (u32, float32) take two registers, high word first, each
// register big-endian on the wire: "ABCD" (mbpoll -B).

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "io/control/ig_status.h"

namespace ig::io::control {

enum class Block : std::uint8_t { Input, Holding };  // FC 04 / FC 03, 06, 16
enum class RegType : std::uint8_t { U16, U32, F32 };

struct RegisterDef {
  const char* name;
  Block block;
  std::uint16_t address;
  RegType type;
  const char* units;
  // Holding registers: accepted range. min_open / max_open: bound excluded.
  double min = 0.0, max = 0.0;
  bool min_open = false, max_open = false;
  const char* description = "";
};

constexpr int register_width(RegType t) { return t == RegType::U16 ? 1 : 2; }
const char* type_name(RegType t);  // "u16", "u32", "float32"

// Input register addresses (read-only status, FC 04).
namespace in {
inline constexpr std::uint16_t kState = 0, kFlags = 1, kFrameCounter = 2, kLastFrameUs = 4, kMedianFrameUs = 6,
                               kLevel1Size = 8, kLevel1Ratio = 9, kTriangles = 11, kPoseAgeMs = 13,
                               kNativeOk = 15, kNativeBad = 17, kCigiOk = 19, kCigiBad = 21, kFgfdmOk = 23,
                               kFgfdmBad = 25, kUptimeS = 27, kModbusClients = 29, kCanLink = 30,
                               kCanPoses = 31, kCanRejected = 33, kCanErrorFrames = 35;
inline constexpr int kCount = 37;
}  // namespace in

// Holding register addresses (controls, FC 03 / 06 / 16).
namespace hold {
inline constexpr std::uint16_t kFreeze = 0, kWireframe = 1, kA1 = 2, kA2 = 4, kAlpha = 6, kLevel0Budget = 8,
                               kFogVisibility = 10, kCapture = 12, kLatencyMode = 13;
inline constexpr int kCount = 14;
}  // namespace hold

inline constexpr std::array<RegisterDef, 30> kRegisterMap = {{
    {"ig_state", Block::Input, in::kState, RegType::U16, "enum", 0, 4, false, false,
     "0 starting, 1 waiting for a pose, 2 running, 3 frozen, 4 stopping"},
    {"status_flags", Block::Input, in::kFlags, RegType::U16, "bits", 0, 63, false, false,
     "bit0 frozen, bit1 wireframe, bit2 reserved, bit3 pose received, bit4 capture pending, bit5 twolevel"},
    {"frame_counter", Block::Input, in::kFrameCounter, RegType::U32, "frames", 0, 4294967295.0, false, false,
     "frames rendered"},
    {"last_frame_time", Block::Input, in::kLastFrameUs, RegType::U32, "us", 0, 4294967295.0, false, false,
     "work time of the last frame (pose + render + readback + log)"},
    {"median_frame_time", Block::Input, in::kMedianFrameUs, RegType::U32, "us", 0, 4294967295.0, false, false,
     "median frame time over the last second"},
    {"level1_size", Block::Input, in::kLevel1Size, RegType::U16, "vertices", 0, 65535, false, false,
     "Level1 grid vertices a side (0 when the method is not twolevel)"},
    {"level1_ratio", Block::Input, in::kLevel1Ratio, RegType::F32, "ratio", -1, 1, false, false,
     "R = Level1 pixels / terrain pixels (-1 before the first measurement)"},
    {"triangles", Block::Input, in::kTriangles, RegType::U32, "triangles", 0, 4294967295.0, false, false,
     "triangles drawn in the last frame"},
    {"pose_age", Block::Input, in::kPoseAgeMs, RegType::U32, "ms", 0, 4294967295.0, false, false,
     "newest pose sample used -> frame start; 4294967295 = no pose received"},
    {"native_ok", Block::Input, in::kNativeOk, RegType::U32, "datagrams", 0, 4294967295.0, false, false,
     "native IGPS datagrams accepted"},
    {"native_bad", Block::Input, in::kNativeBad, RegType::U32, "datagrams", 0, 4294967295.0, false, false,
     "native IGPS datagrams rejected"},
    {"cigi_ok", Block::Input, in::kCigiOk, RegType::U32, "datagrams", 0, 4294967295.0, false, false,
     "CIGI datagrams accepted"},
    {"cigi_bad", Block::Input, in::kCigiBad, RegType::U32, "datagrams", 0, 4294967295.0, false, false,
     "CIGI datagrams rejected"},
    {"fgfdm_ok", Block::Input, in::kFgfdmOk, RegType::U32, "datagrams", 0, 4294967295.0, false, false,
     "FGNetFDM datagrams accepted"},
    {"fgfdm_bad", Block::Input, in::kFgfdmBad, RegType::U32, "datagrams", 0, 4294967295.0, false, false,
     "FGNetFDM datagrams rejected"},
    {"uptime", Block::Input, in::kUptimeS, RegType::U32, "s", 0, 4294967295.0, false, false,
     "seconds since the Modbus server started"},
    {"modbus_clients", Block::Input, in::kModbusClients, RegType::U16, "clients", 0, 65535, false, false,
     "Modbus TCP clients connected now"},
    {"can_link", Block::Input, in::kCanLink, RegType::U16, "enum", 0, 2, false, false,
     "CAN source: 0 none, 1 receiving, 2 interface unusable, retrying"},
    {"can_poses", Block::Input, in::kCanPoses, RegType::U32, "poses", 0, 4294967295.0, false, false,
     "poses from the CAN source (CANaerospace cycles + FD frames)"},
    {"can_rejected", Block::Input, in::kCanRejected, RegType::U32, "frames", 0, 4294967295.0, false, false,
     "CAN frames rejected by the decoders"},
    {"can_error_frames", Block::Input, in::kCanErrorFrames, RegType::U32, "frames", 0, 4294967295.0, false, false,
     "CAN error frames received (bus-off included)"},

    {"freeze", Block::Holding, hold::kFreeze, RegType::U16, "bool", 0, 1, false, false,
     "1: keep rendering the last pose, pose input ignored"},
    {"wireframe", Block::Holding, hold::kWireframe, RegType::U16, "bool", 0, 1, false, false,
     "1: terrain drawn as lines (GL_LINE)"},
    // Ranges: the options structs' (options/twolevel_options.h, shading_options.h).
    {"lod_a1", Block::Holding, hold::kA1, RegType::F32, "ratio", 0, 1, true, true,
     "Level1 grows when R < a1; 0 < a1 < a2"},
    {"lod_a2", Block::Holding, hold::kA2, RegType::F32, "ratio", 0, 1, true, true,
     "Level1 shrinks when R > a2; a1 < a2 < 1"},
    {"band_alpha", Block::Holding, hold::kAlpha, RegType::F32, "factor", 0, options::TwoLevelOptions::kMaxAlpha, true,
     false, "band factor alpha (method rebuilt at the next frame boundary)"},
    {"level0_budget", Block::Holding, hold::kLevel0Budget, RegType::U32, "triangles",
     options::TwoLevelOptions::kMinLevel0Budget, options::TwoLevelOptions::kMaxLevel0Budget, false, false,
     "Level0 triangle budget (method rebuilt at the next frame boundary)"},
    {"fog_visibility", Block::Holding, hold::kFogVisibility, RegType::F32, "m", 0,
     options::ShadingOptions::kMaxFogVisibilityM, false, false, "fog visibility; 0 = no fog"},
    {"capture", Block::Holding, hold::kCapture, RegType::U16, "trigger", 0, 1, false, false,
     "write 1: the next frame is saved as PNG; reads 0 again once taken"},
    {"latency_mode", Block::Holding, hold::kLatencyMode, RegType::U16, "enum", 0, 2, false, false,
     "pose latency: 0 smooth, 1 latest, 2 CIGI synchronous (needs a CIGI source; applied at the frame boundary)"},
}};

int block_size(Block b);  // registers in the block (in::kCount / hold::kCount)

// Word order ABCD: high word first. Floats are packed by hand (libmodbus
// 3.1.6's modbus_get_float_* are broken).
inline void put_u32(std::uint16_t* r, std::uint32_t v) {
  r[0] = std::uint16_t(v >> 16);
  r[1] = std::uint16_t(v & 0xFFFFu);
}
inline std::uint32_t get_u32(const std::uint16_t* r) { return (std::uint32_t(r[0]) << 16) | r[1]; }
void put_f32(std::uint16_t* r, float v);
float get_f32(const std::uint16_t* r);

// Status -> the input registers; controls <-> the holding registers.
void encode_status(const IgStatus& s, std::span<std::uint16_t, in::kCount> regs);
void encode_controls(const IgControls& c, std::span<std::uint16_t, hold::kCount> regs);
IgControls decode_controls(std::span<const std::uint16_t, hold::kCount> regs);
// Every holding value in its range and a1 < a2: nullopt, else the reason
// (names the register).
std::optional<std::string> validate_controls(std::span<const std::uint16_t, hold::kCount> regs);
// The value a register holds, as a double (tests, docs).
double register_value(const RegisterDef& def, const std::uint16_t* block_regs);

}  // namespace ig::io::control
