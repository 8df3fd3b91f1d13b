#pragma once
// What the Modbus server (io/control/modbus_server.h) publishes and accepts:
// a status snapshot the frame loop copies in once per frame, and the control
// values an instructor station sets. Plain values, no GL, no libmodbus, so
// the frame loop and the tests use them without the server.

#include <cstdint>

#include "options/shading_options.h"
#include "options/twolevel_options.h"

namespace ig::io::control {

// IG state (input register 0).
enum class IgState : std::uint16_t {
  Starting = 0,     // no frame rendered yet
  WaitingPose = 1,  // rendering the scenario's initial pose: no packet received yet
  Running = 2,      // rendering received poses
  Frozen = 3,       // freeze on: the last pose is rendered again, pose input ignored
  Stopping = 4,     // last frame rendered, process exiting
};

// Bits of the status flags (input register 1).
enum StatusFlag : std::uint16_t {
  kFlagFrozen = 1u << 0,
  kFlagWireframe = 1u << 1,
  kFlagReserved2 = 1u << 2,        // reserved (0)
  kFlagPoseReceived = 1u << 3,     // at least one pose packet accepted
  kFlagCapturePending = 1u << 4,   // a capture trigger waits for the next frame
  kFlagTwoLevel = 1u << 5,         // the channel's method is twolevel (Level1 registers meaningful)
};

struct PacketCounts {
  std::uint32_t ok = 0;
  std::uint32_t bad = 0;
};

// One frame's status, published by the frame loop after the frame.
struct IgStatus {
  IgState state = IgState::Starting;
  std::uint16_t flags = 0;
  std::uint32_t frame_counter = 0;      // frames rendered so far
  std::uint32_t last_frame_us = 0;      // work time of the last frame (pose, render, readback, log)
  std::uint32_t median_frame_us = 0;    // median of the frames of the last second
  std::uint16_t level1_size = 0;        // Level1 vertices a side (0: not twolevel)
  float level1_ratio = -1.0f;           // R = Level1 pixels / terrain pixels (-1: not measured)
  std::uint32_t triangles = 0;          // triangles drawn in the last frame
  std::uint32_t pose_age_ms = 0xFFFFFFFFu;  // newest sample used -> frame start (0xFFFFFFFF: no pose)
  PacketCounts native, cigi, fgfdm;     // cumulative accepted / rejected datagrams per source
  std::uint32_t uptime_s = 0;           // since the server started
  // CAN pose source (ig serve --can): link 0 = no CAN source, 1 = receiving,
  // 2 = unusable and retrying (no AF_CAN, missing, down, removed).
  std::uint16_t can_link = 0;
  std::uint32_t can_poses = 0;          // poses formed (CANaerospace cycles + FD frames)
  std::uint32_t can_rejected = 0;       // frames rejected by the decoders
  std::uint32_t can_error_frames = 0;   // CAN error frames (bus-off included)
  std::uint16_t modbus_clients = 0;     // filled in by the server itself
};

// The holding registers' values. The server keeps the requested values; the
// frame loop reads them at a frame boundary and applies them. Defaults and
// ranges are the options structs' (register_map.h).
struct IgControls {
  bool freeze = false;
  bool wireframe = false;
  // Level1 thresholds (TwoLevelOptions::check_thresholds).
  float a1 = float(options::TwoLevelOptions{}.a1), a2 = float(options::TwoLevelOptions{}.a2);
  float alpha = float(options::TwoLevelOptions{}.alpha);  // band factor (method rebuilt when written)
  // Level0 triangles (method rebuilt when written). The IG starts the
  // server with its resolved budget; this is "auto" at the reference display.
  std::uint32_t level0_budget = options::TwoLevelOptions::kReferenceLevel0Budget;
  float fog_visibility_m = float(options::ShadingOptions{}.fog_visibility_m);  // 0 = no fog
  bool capture = false;                // capture-next-frame trigger
  std::uint16_t latency_mode = 0;      // 0 smooth, 1 latest, 2 CIGI synchronous (io::LatencyMode)
};

// What changed since the frame loop last looked (ModbusServer::take_controls).
struct ControlUpdate {
  IgControls controls;        // the whole current image
  bool thresholds = false;    // a1 or a2 written
  bool rebuild = false;       // alpha or Level0 budget written
  bool fog = false;
  bool capture = false;       // capture the next frame (the register is already reset to 0)
  bool latency = false;       // latency_mode written
  bool any() const { return thresholds || rebuild || fog || capture || latency; }
};

}  // namespace ig::io::control
