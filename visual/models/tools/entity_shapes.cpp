#include "models/tools/entity_shapes.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include <glm/geometric.hpp>

namespace ig::models::shapes {

using designs::Detail;

namespace {

// A loft's axes: stations go along `axis`; a section's x runs along `u`, its y along `v`.
struct Frame {
  glm::vec3 axis, u, v;
};
constexpr glm::vec3 X{1, 0, 0}, Y{0, 1, 0}, Z{0, 0, 1};

// One section of a loft: at `along` on the axis, the unit section scaled by
// (su, sv) about (cu, cv).
struct Station {
  float along, su, sv, cu = 0.0f, cv = 0.0f;
};

std::uint32_t add_vertex(MeshData& m, glm::vec3 p, glm::vec3 n, glm::vec2 uv) {
  m.positions.push_back(p);
  m.normals.push_back(n);
  m.texcoords.push_back(uv);
  return std::uint32_t(m.positions.size() - 1);
}

// Winding from the outward direction, so no part can face inwards by a slip
// in vertex order.
void add_triangle(MeshData& m, std::uint32_t a, std::uint32_t b, std::uint32_t c, glm::vec3 outward) {
  const glm::vec3 f = glm::cross(m.positions[b] - m.positions[a], m.positions[c] - m.positions[a]);
  if (glm::dot(f, outward) < 0.0f) std::swap(b, c);
  m.indices.insert(m.indices.end(), {a, b, c});
}

void add_box(MeshData& m, glm::vec3 lo, glm::vec3 hi) {
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    for (int side = 0; side < 2; ++side) {
      glm::vec3 n(0.0f);
      n[a] = side ? 1.0f : -1.0f;
      glm::vec3 corner[4];
      for (int k = 0; k < 4; ++k) {
        corner[k][a] = side ? hi[a] : lo[a];
        corner[k][b] = (k == 1 || k == 2) ? hi[b] : lo[b];
        corner[k][c] = (k >= 2) ? hi[c] : lo[c];
      }
      const std::uint32_t i0 = add_vertex(m, corner[0], n, {0, 0});
      add_vertex(m, corner[1], n, {1, 0});
      add_vertex(m, corner[2], n, {1, 1});
      add_vertex(m, corner[3], n, {0, 1});
      add_triangle(m, i0, i0 + 1, i0 + 2, n);
      add_triangle(m, i0, i0 + 2, i0 + 3, n);
    }
  }
}

// n points on the unit circle, counter-clockwise from +x; computed in double
// so the four extremes (n a multiple of 4) are exactly +-1.
std::vector<glm::vec2> circle(int n) {
  std::vector<glm::vec2> s;
  for (int k = 0; k < n; ++k) {
    const double t = 2.0 * M_PI * k / n;
    double c = std::cos(t), si = std::sin(t);
    if (std::fabs(c) < 1e-12) c = 0.0;
    if (std::fabs(si) < 1e-12) si = 0.0;
    s.emplace_back(float(c), float(si));
  }
  return s;
}

// A closed tube through the stations of a convex, counter-clockwise unit
// section: smooth sides (the seam repeated so texture u runs 0..1 around,
// v 0..1 along), a flat fan cap at each end. Triangles:
// designs::loft_triangles(section.size(), stations.size()).
void add_loft(MeshData& m, const std::vector<glm::vec2>& section, const std::vector<Station>& st, const Frame& f) {
  const std::size_t n = section.size(), s = st.size();
  // Outward normal of the section at each point: the mean of its two edges'.
  std::vector<glm::vec2> n2(n);
  for (std::size_t k = 0; k < n; ++k) {
    const glm::vec2 e0 = section[k] - section[(k + n - 1) % n], e1 = section[(k + 1) % n] - section[k];
    n2[k] = glm::normalize(glm::normalize(glm::vec2(e0.y, -e0.x)) + glm::normalize(glm::vec2(e1.y, -e1.x)));
  }
  auto point = [&](const Station& t, glm::vec2 p) {
    return f.axis * t.along + f.u * (t.cu + t.su * p.x) + f.v * (t.cv + t.sv * p.y);
  };
  auto normal = [&](const Station& t, glm::vec2 nn) {
    const glm::vec2 e = glm::normalize(glm::vec2(nn.x / std::max(t.su, 1e-3f), nn.y / std::max(t.sv, 1e-3f)));
    return glm::normalize(f.u * e.x + f.v * e.y);
  };
  const float a0 = st.front().along, a1 = st.back().along;
  const std::uint32_t base = std::uint32_t(m.positions.size());
  for (std::size_t i = 0; i < s; ++i) {
    const float v = (st[i].along - a0) / (a1 - a0);
    for (std::size_t k = 0; k <= n; ++k) {
      add_vertex(m, point(st[i], section[k % n]), normal(st[i], n2[k % n]), {float(k) / float(n), v});
    }
  }
  const std::uint32_t ring = std::uint32_t(n + 1);
  for (std::uint32_t i = 0; i + 1 < s; ++i) {
    for (std::uint32_t k = 0; k < n; ++k) {
      const std::uint32_t a = base + i * ring + k, b = a + 1, c = a + ring + 1, d = a + ring;
      const glm::vec3 out = m.normals[a] + m.normals[b] + m.normals[c] + m.normals[d];
      add_triangle(m, a, b, c, out);
      add_triangle(m, a, c, d, out);
    }
  }
  for (const std::size_t end : {std::size_t(0), s - 1}) {
    const glm::vec3 out = end == 0 ? -f.axis : f.axis;
    const std::uint32_t cap = std::uint32_t(m.positions.size());
    for (std::size_t k = 0; k < n; ++k) {
      add_vertex(m, point(st[end], section[k]), out, {float(k) / float(n), end == 0 ? 0.0f : 1.0f});
    }
    for (std::uint32_t k = 1; k + 1 < n; ++k) add_triangle(m, cap, cap + k, cap + k + 1, out);
  }
}

// The stations at `keep` of `all` (a coarse LOD keeps the fine one's extremes).
std::vector<Station> pick(const std::vector<Station>& all, std::initializer_list<int> keep) {
  std::vector<Station> out;
  for (int i : keep) out.push_back(all[std::size_t(i)]);
  return out;
}

MeshData mesh(std::string name, int material) {
  MeshData m;
  m.name = std::move(name);
  m.material = material;
  return m;
}

int add_node(EntityModel& e, std::string name, int parent, glm::vec3 t, int mesh_index) {
  e.nodes.push_back({std::move(name), parent, t, mesh_index});
  return int(e.nodes.size() - 1);
}

int add_mesh(EntityModel& e, MeshData m) {
  e.meshes.push_back(std::move(m));
  return int(e.meshes.size() - 1);
}

// A wing-like surface along `f.axis` from -half_span to +half_span (or 0 to
// span): an elliptic airfoil of `points`, `pieces` spanwise pieces, chord and
// thickness tapering linearly with |along| from root to tip.
std::vector<Station> surface(float from, float to, int pieces, float root_chord, float tip_chord, float root_t,
                             float tip_t, float chord_centre, float thick_centre) {
  std::vector<Station> st;
  const float reach = std::max(std::fabs(from), std::fabs(to));
  for (int k = 0; k <= pieces; ++k) {
    const float a = from + (to - from) * float(k) / float(pieces);
    const float w = reach > 0.0f ? std::fabs(a) / reach : 0.0f;
    st.push_back({a, 0.5f * (root_chord + (tip_chord - root_chord) * w), 0.5f * (root_t + (tip_t - root_t) * w),
                  chord_centre, thick_centre});
  }
  return st;
}

// The fuselage livery: white, a blue cheat line along both sides, a red
// band round the tail, a dark anti-glare panel ahead of the windscreen.
// u runs round the fuselage from its left side (+X) over the top; v from tail to nose.
TextureData livery(int size) {
  TextureData t;
  t.name = "livery";
  t.width = t.height = size;
  t.rgba.resize(std::size_t(size) * std::size_t(size) * 4);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const double u = (x + 0.5) / size, v = (y + 0.5) / size;
      const double up = std::sin(2.0 * M_PI * u);  // +1 on top, 0 at the sides
      std::uint8_t c[4] = {240, 240, 245, 255};
      if (std::fabs(up) < 0.12) {
        c[0] = 20, c[1] = 50, c[2] = 140;
      } else if (v < 0.18) {
        c[0] = 200, c[1] = 30, c[2] = 25;
      } else if (v > 0.78 && up > 0.8) {
        c[0] = c[1] = c[2] = 40;
      }
      std::copy(c, c + 4, &t.rgba[(std::size_t(y) * std::size_t(size) + std::size_t(x)) * 4]);
    }
  }
  return t;
}

}  // namespace

std::uint64_t EntityModel::triangles() const {
  std::uint64_t n = 0;
  for (const NodeData& node : nodes) {
    if (node.mesh >= 0) n += meshes[std::size_t(node.mesh)].triangles();
  }
  return n;
}

EntityModel build_aircraft(Detail d) {
  const designs::AircraftResolution r = designs::aircraft_resolution(d);
  const bool fine = d == Detail::Fine;
  EntityModel e;
  e.file = fine ? "aircraft.glb" : "aircraft_coarse.glb";
  e.materials = {{"livery", fine ? glm::vec4(1.0f) : glm::vec4(0.92f, 0.92f, 0.95f, 1.0f), fine, false, false},
                 {"wing_paint", {0.80f, 0.14f, 0.10f, 1.0f}},
                 {"canopy_glass", {0.25f, 0.35f, 0.45f, 0.35f}, false, true, false},
                 {"propeller", {0.10f, 0.10f, 0.10f, 1.0f}, false, false, true}};
  if (fine) e.texture = livery(designs::kAircraftTextureSize);

  const Frame along_z{Z, X, Y}, along_x{X, Z, Y}, along_y{Y, Z, X};
  // Fuselage: tail cone at z -4.6 to the cowling at 3.4; deepest at z 1.0
  // (belly at y -0.70).
  const std::vector<Station> fuselage = {{-4.6f, 0.08f, 0.12f, 0, 0.35f}, {-3.5f, 0.25f, 0.30f, 0, 0.25f},
                                         {-2.0f, 0.45f, 0.55f, 0, 0.10f}, {-0.5f, 0.60f, 0.70f, 0, 0.05f},
                                         {1.0f, 0.60f, 0.70f, 0, 0.00f},  {2.5f, 0.55f, 0.60f, 0, -0.05f},
                                         {3.4f, 0.40f, 0.42f, 0, -0.05f}};
  const std::vector<Station> canopy = {{0.0f, 0.05f, 0.05f, 0, 0.55f}, {0.4f, 0.38f, 0.30f, 0, 0.60f},
                                       {0.9f, 0.42f, 0.38f, 0, 0.60f}, {1.4f, 0.36f, 0.25f, 0, 0.58f},
                                       {1.8f, 0.05f, 0.05f, 0, 0.55f}};
  MeshData m = mesh("fuselage", 0);
  add_loft(m, circle(r.fuselage_points), fine ? fuselage : pick(fuselage, {0, 2, 4, 6}), along_z);
  const int fuselage_mesh = add_mesh(e, std::move(m));
  m = mesh("canopy", 2);
  add_loft(m, circle(r.canopy_points), fine ? canopy : pick(canopy, {0, 2, 4}), along_z);
  const int canopy_mesh = add_mesh(e, std::move(m));
  // Wing: 12 m span at y -0.3, chord 1.7 m at the root, 1.1 m at the tips.
  m = mesh("wing", 1);
  add_loft(m, circle(r.wing_points),
           surface(-designs::kAircraftSpan / 2, designs::kAircraftSpan / 2, r.wing_sections, 1.7f, 1.1f, 0.18f, 0.10f,
                   0.6f, -0.3f),
           along_x);
  const int wing_mesh = add_mesh(e, std::move(m));
  // Tail: stabiliser and fin 0.8 m chord about their nodes; elevators and
  // rudder hinged at the trailing edge (their node origin), reaching aft.
  m = mesh("horizontal_stabilizer", 1);
  add_loft(m, circle(r.tail_points), surface(-1.8f, 1.8f, 1, 0.8f, 0.8f, 0.08f, 0.08f, 0.0f, 0.0f), along_x);
  const int stabilizer_mesh = add_mesh(e, std::move(m));
  m = mesh("elevator", 1);
  add_loft(m, circle(r.tail_points), surface(-0.8f, 0.8f, 1, 0.4f, 0.4f, 0.06f, 0.06f, -0.2f, 0.0f), along_x);
  const int elevator_mesh = add_mesh(e, std::move(m));
  m = mesh("vertical_fin", 1);
  add_loft(m, circle(r.tail_points), surface(0.0f, 1.5f, 1, 0.8f, 0.8f, 0.08f, 0.08f, 0.0f, 0.0f), along_y);
  const int fin_mesh = add_mesh(e, std::move(m));
  m = mesh("rudder", 1);
  add_loft(m, circle(r.tail_points), surface(0.0f, 1.5f, 1, 0.5f, 0.5f, 0.06f, 0.06f, -0.25f, 0.0f), along_y);
  const int rudder_mesh = add_mesh(e, std::move(m));
  // Propeller: the spinner (tip 0.4 m ahead of the cowling) and two blades
  // of 0.95 m radius, thin: double-sided.
  m = mesh("propeller", 3);
  const std::vector<Station> spinner = {{0.0f, 0.2f, 0.2f}, {0.25f, 0.15f, 0.15f}, {0.4f, 0.02f, 0.02f}};
  add_loft(m, circle(r.spinner_points), fine ? spinner : pick(spinner, {0, 2}), along_z);
  add_box(m, {0.15f, -0.06f, 0.10f}, {0.95f, 0.06f, 0.16f});
  add_box(m, {-0.95f, -0.06f, 0.10f}, {-0.15f, 0.06f, 0.16f});
  const int propeller_mesh = add_mesh(e, std::move(m));

  const int root = add_node(e, "aircraft", -1, {0, 0, 0}, -1);
  add_node(e, "fuselage", root, {0, 0, 0}, fuselage_mesh);
  add_node(e, "canopy", root, {0, 0, 0}, canopy_mesh);
  add_node(e, "wing", root, {0, 0, 0}, wing_mesh);
  const int stabilizer = add_node(e, "horizontal_stabilizer", root, {0, 0.35f, -4.0f}, stabilizer_mesh);
  add_node(e, "elevator_left", stabilizer, {1.0f, 0, -0.4f}, elevator_mesh);  // +X is the left in glTF
  add_node(e, "elevator_right", stabilizer, {-1.0f, 0, -0.4f}, elevator_mesh);
  const int fin = add_node(e, "vertical_fin", root, {0, 0.35f, -4.0f}, fin_mesh);
  add_node(e, "rudder", fin, {0, 0, -0.4f}, rudder_mesh);
  add_node(e, "propeller", root, {0, -0.05f, 3.4f}, propeller_mesh);
  return e;
}

EntityModel build_ground_vehicle(Detail d) {
  const designs::VehicleResolution r = designs::vehicle_resolution(d);
  const bool fine = d == Detail::Fine;
  EntityModel e;
  e.file = fine ? "ground_vehicle.glb" : "ground_vehicle_coarse.glb";
  e.materials = {{"olive_drab", {0.30f, 0.36f, 0.18f, 1.0f}},
                 {"tyre", {0.04f, 0.04f, 0.04f, 1.0f}},
                 {"gun_metal", {0.18f, 0.19f, 0.17f, 1.0f}}};
  // Hull: 5.6 m long, its floor 0.45 m above the ground.
  MeshData m = mesh("hull", 0);
  if (fine) {
    add_box(m, {-1.1f, 0.45f, -2.8f}, {1.1f, 1.55f, 2.8f});
    add_box(m, {-1.0f, 1.55f, -2.6f}, {1.0f, 1.9f, 1.8f});
  } else {
    add_box(m, {-1.1f, 0.45f, -2.8f}, {1.1f, 1.9f, 2.8f});
  }
  const int hull_mesh = add_mesh(e, std::move(m));
  // Wheel: 0.9 m across, 0.4 m wide, about its node's X axis; the fine one
  // with rounded shoulders.
  m = mesh("wheel", 1);
  const std::vector<Station> tyre = {{-0.2f, 0.40f, 0.40f}, {-0.15f, 0.45f, 0.45f}, {0.15f, 0.45f, 0.45f},
                                     {0.2f, 0.40f, 0.40f}};
  const std::vector<Station> coarse_tyre = {{-0.2f, 0.45f, 0.45f}, {0.2f, 0.45f, 0.45f}};
  add_loft(m, circle(r.wheel_points), fine ? tyre : coarse_tyre, Frame{X, Z, Y});
  const int wheel_mesh = add_mesh(e, std::move(m));
  // Turret: 1.9 m across at its ring, 0.65 m tall, about its node's Y axis.
  m = mesh("turret", 0);
  const std::vector<Station> turret = {{0.0f, 0.95f, 0.95f}, {0.5f, 0.85f, 0.85f}, {0.65f, 0.6f, 0.6f}};
  add_loft(m, circle(r.turret_points), fine ? turret : pick(turret, {0, 2}), Frame{Y, X, Z});
  const int turret_mesh = add_mesh(e, std::move(m));
  // Gun: a 2.3 m barrel from the trunnion (its node) forwards.
  m = mesh("gun", 2);
  if (r.gun_points > 0) {
    add_loft(m, circle(r.gun_points), {{0.0f, 0.06f, 0.06f}, {2.3f, 0.06f, 0.06f}}, Frame{Z, X, Y});
  } else {
    add_box(m, {-0.06f, -0.06f, 0.0f}, {0.06f, 0.06f, 2.3f});
  }
  const int gun_mesh = add_mesh(e, std::move(m));

  const int root = add_node(e, "ground_vehicle", -1, {0, 0, 0}, -1);
  add_node(e, "hull", root, {0, 0, 0}, hull_mesh);
  const int turret_node = add_node(e, "turret", root, {0, 1.9f, 0.2f}, turret_mesh);
  add_node(e, "gun", turret_node, {0, 0.35f, 0.7f}, gun_mesh);
  const float axle_z[4] = {2.1f, 0.7f, -0.7f, -2.1f};  // front to rear
  for (int side = 0; side < 2; ++side) {
    for (int k = 0; k < 4; ++k) {
      const std::string name = std::string(side == 0 ? "wheel_left_" : "wheel_right_") + std::to_string(k + 1);
      add_node(e, name, root, {side == 0 ? 1.05f : -1.05f, 0.45f, axle_z[k]}, wheel_mesh);
    }
  }
  return e;
}

EntityModel build_ship(Detail d) {
  const designs::ShipResolution r = designs::ship_resolution(d);
  const bool fine = d == Detail::Fine;
  EntityModel e;
  e.file = fine ? "ship.glb" : "ship_coarse.glb";
  e.materials = {{"hull_grey", {0.40f, 0.44f, 0.48f, 1.0f}},
                 {"superstructure_white", {0.80f, 0.82f, 0.84f, 1.0f}},
                 {"radar_black", {0.08f, 0.08f, 0.08f, 1.0f}}};
  // Hull: 60 m, 9 m beam amidships, keel 3 m below the waterline, the deck
  // 3 m above it rising to 4.2 m at the bow. Section: deck on top (y 0),
  // keel at the bottom (y -1), counter-clockwise from the keel.
  const std::vector<glm::vec2> section =
      fine ? std::vector<glm::vec2>{{0, -1},       {0.45f, -0.95f}, {0.8f, -0.7f},   {0.97f, -0.35f}, {1, 0},
                                    {0, 0},        {-1, 0},         {-0.97f, -0.35f}, {-0.8f, -0.7f}, {-0.45f, -0.95f}}
           : std::vector<glm::vec2>{{0.7f, -1}, {1, 0}, {-1, 0}, {-0.7f, -1}};
  const std::vector<Station> hull = {{-30, 3.9f, 6.0f, 0, 3.0f}, {-24, 4.3f, 6.0f, 0, 3.0f}, {-14, 4.5f, 6.0f, 0, 3.0f},
                                     {0, 4.5f, 6.0f, 0, 3.0f},   {10, 4.3f, 6.0f, 0, 3.1f},  {19, 3.4f, 5.8f, 0, 3.4f},
                                     {26, 2.0f, 5.4f, 0, 3.8f},  {30, 0.05f, 5.0f, 0, 4.2f}};
  MeshData m = mesh("hull", 0);
  add_loft(m, section, fine ? hull : pick(hull, {0, 3, 7}), Frame{Z, X, Y});
  const int hull_mesh = add_mesh(e, std::move(m));
  m = mesh("superstructure", 1);
  if (fine) {
    add_box(m, {-3.5f, 3.0f, -8.0f}, {3.5f, 8.0f, 4.0f});
    add_box(m, {-2.5f, 8.0f, -4.0f}, {2.5f, 10.0f, 2.0f});
  } else {
    add_box(m, {-3.5f, 3.0f, -8.0f}, {3.5f, 10.0f, 4.0f});
  }
  const int superstructure_mesh = add_mesh(e, std::move(m));
  // Mast: 5 m above the bridge roof; the radar antenna (3.2 m) on top.
  m = mesh("mast", 1);
  if (r.mast_points > 0) {
    add_loft(m, circle(r.mast_points), {{0.0f, 0.25f, 0.25f}, {5.0f, 0.25f, 0.25f}}, Frame{Y, X, Z});
  } else {
    add_box(m, {-0.25f, 0.0f, -0.25f}, {0.25f, 5.0f, 0.25f});
  }
  const int mast_mesh = add_mesh(e, std::move(m));
  m = mesh("radar", 2);
  add_box(m, {-1.6f, 0.0f, -0.25f}, {1.6f, 0.6f, 0.25f});
  const int radar_mesh = add_mesh(e, std::move(m));

  const int root = add_node(e, "ship", -1, {0, 0, 0}, -1);
  add_node(e, "hull", root, {0, 0, 0}, hull_mesh);
  add_node(e, "superstructure", root, {0, 0, 0}, superstructure_mesh);
  if (r.funnel_points > 0) {
    m = mesh("funnel", 2);
    add_loft(m, circle(r.funnel_points), {{0.0f, 0.9f, 1.4f}, {4.0f, 0.9f, 1.4f}}, Frame{Y, X, Z});
    add_node(e, "funnel", root, {0, 8.0f, -6.0f}, add_mesh(e, std::move(m)));
  }
  const int mast = add_node(e, "mast", root, {0, 10.0f, -1.0f}, mast_mesh);
  add_node(e, "radar", mast, {0, 5.0f, 0}, radar_mesh);
  return e;
}

EntityModel build_far(const std::string& file, glm::vec3 lo, glm::vec3 hi, glm::vec4 colour) {
  EntityModel e;
  e.file = file;
  e.materials = {{"far", colour}};
  MeshData m = mesh("far", 0);
  add_box(m, lo, hi);
  add_node(e, "far", -1, {0, 0, 0}, add_mesh(e, std::move(m)));
  return e;
}

}  // namespace ig::models::shapes
