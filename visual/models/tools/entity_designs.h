#pragma once
// The design of the project's own entity models (make_entity_models writes
// them; visual/models/test/entity_models_test.cpp loads them back and checks
// these figures). glTF axes: metres, +Y up, +Z the front, -X the right.
//
// Triangle counts are arithmetic on the parts' resolutions, not counted from
// the built meshes, so a builder that makes the wrong number of triangles,
// or a loader that loses or duplicates some, fails the test.

#include <array>
#include <cstdint>

namespace ig::models::designs {

enum class Detail { Fine, Coarse };

// A closed loft of a convex section of `points` through `stations` stations
// (an extrusion is a loft of two or more stations): the sides plus a fan
// cap at each end.
constexpr std::uint64_t loft_triangles(int points, int stations) {
  return 2ull * std::uint64_t(points) * std::uint64_t(stations - 1) + 2ull * std::uint64_t(points - 2);
}
constexpr std::uint64_t kBoxTriangles = 12;

struct Box3 {
  std::array<float, 3> min, max;
};

// ---- Aircraft: a light single-engine low-wing monoplane, 12 m span. ----
// Articulated: "propeller" (spins about its local Z), "rudder" (about its
// local Y, hinge at the fin's trailing edge), "elevator_left" and
// "elevator_right" (about their local X, one mesh instanced twice).
struct AircraftResolution {
  int fuselage_points, fuselage_stations;  // circle sections (multiple of 4)
  int canopy_points, canopy_stations;
  int wing_points, wing_sections;          // airfoil profile points, spanwise pieces
  int tail_points;                         // stabiliser, elevators, fin, rudder profiles (1 piece each)
  int spinner_points, spinner_stations;
};
constexpr AircraftResolution aircraft_resolution(Detail d) {
  return d == Detail::Fine ? AircraftResolution{32, 7, 24, 5, 16, 12, 12, 24, 3}
                           : AircraftResolution{8, 4, 6, 3, 4, 2, 4, 6, 2};
}
constexpr std::uint64_t aircraft_triangles(Detail d) {
  const AircraftResolution r = aircraft_resolution(d);
  return loft_triangles(r.fuselage_points, r.fuselage_stations) + loft_triangles(r.canopy_points, r.canopy_stations) +
         loft_triangles(r.wing_points, r.wing_sections + 1) +
         4 * loft_triangles(r.tail_points, 2) +  // stabiliser, two elevators (one mesh, two nodes), fin
         loft_triangles(r.tail_points, 2) +      // rudder
         loft_triangles(r.spinner_points, r.spinner_stations) + 2 * kBoxTriangles;  // two blades
}
constexpr float kAircraftSpan = 12.0f;
// Wing tips (x), belly under the cabin and fin top (y), rudder trailing edge
// and spinner tip (z).
constexpr Box3 kAircraftBounds{{-6.0f, -0.70f, -4.9f}, {6.0f, 1.85f, 3.8f}};
constexpr int kAircraftTextureSize = 64;  // the fine model's fuselage livery, RGBA

// ---- Ground vehicle: an eight-wheeled armoured vehicle, 6 m long. ----
// Articulated: "turret" (about its local Y), "gun" (child of the turret,
// about its local X), "wheel_left_1".."wheel_left_4", "wheel_right_1"..
// "wheel_right_4" (about their local X; one wheel mesh drawn eight times).
struct VehicleResolution {
  int wheel_points, wheel_stations;
  int turret_points, turret_stations;
  int gun_points;   // 0: the barrel is a box
  int hull_boxes;
};
constexpr VehicleResolution vehicle_resolution(Detail d) {
  return d == Detail::Fine ? VehicleResolution{32, 4, 24, 3, 12, 2} : VehicleResolution{8, 2, 8, 2, 0, 1};
}
constexpr int kVehicleWheels = 8;
constexpr std::uint64_t vehicle_triangles(Detail d) {
  const VehicleResolution r = vehicle_resolution(d);
  return kVehicleWheels * loft_triangles(r.wheel_points, r.wheel_stations) +
         loft_triangles(r.turret_points, r.turret_stations) +
         (r.gun_points > 0 ? loft_triangles(r.gun_points, 2) : kBoxTriangles) + std::uint64_t(r.hull_boxes) * kBoxTriangles;
}
// Wheels' outer faces (x), ground and turret roof (y), hull's rear and the
// gun's muzzle (z).
constexpr Box3 kVehicleBounds{{-1.25f, 0.0f, -2.8f}, {1.25f, 2.55f, 3.2f}};

// ---- Ship: a 60 m patrol vessel, origin on the waterline amidships. ----
// Articulated: "radar" (about its local Y, on top of the mast).
struct ShipResolution {
  int hull_points, hull_stations;
  int mast_points;       // 0: the mast is a box
  int superstructure_boxes;
  int funnel_points;     // 0: no funnel
};
constexpr ShipResolution ship_resolution(Detail d) {
  return d == Detail::Fine ? ShipResolution{10, 8, 12, 2, 16} : ShipResolution{4, 3, 0, 1, 0};
}
constexpr std::uint64_t ship_triangles(Detail d) {
  const ShipResolution r = ship_resolution(d);
  return loft_triangles(r.hull_points, r.hull_stations) + std::uint64_t(r.superstructure_boxes) * kBoxTriangles +
         (r.mast_points > 0 ? loft_triangles(r.mast_points, 2) : kBoxTriangles) +
         (r.funnel_points > 0 ? loft_triangles(r.funnel_points, 2) : 0) + kBoxTriangles;  // + the radar antenna
}
constexpr float kShipLength = 60.0f;
// Deck edges amidships (x), keel and radar top (y), stern and bow (z).
constexpr Box3 kShipBounds{{-4.5f, -3.0f, -30.0f}, {4.5f, 15.6f, 30.0f}};

}  // namespace ig::models::designs
