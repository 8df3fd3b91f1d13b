#pragma once
// The eye: position in double precision (terrain-local ENU metres), attitude
// as a body->world quaternion (body x right, y forward, z up; see io/pose.h
// for the heading/pitch/roll convention), symmetric perspective frustum.
//
// Rendering is camera-relative: the GPU only ever sees positions minus the eye
// position (computed in double here), so precision does not depend on how far
// the scene is from the origin. Depth is reversed-Z (near -> 1, far -> 0) into
// a 32-bit float buffer (glClipControl ZERO_TO_ONE).
//
// Methods see a terrain-local camera (TerrainScene::local_camera): position
// relative to the DEM's sample (0, 0), and earth_radius_m > 0 when the scene
// is drawn with Earth curvature (terrain/earth_curvature.h), so culling and
// the shaders' drop agree without each method knowing about it.

#include <array>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace ig::render {

struct Camera {
  glm::dvec3 position{0.0};
  glm::dquat attitude{1.0, 0.0, 0.0, 0.0};
  double fov_y_deg = 60.0;
  double aspect = 4.0 / 3.0;
  double near_m = 0.5;
  double far_m = 300000.0;
  // > 0: terrain is drawn lowered by the sphere's drop below the eye's
  // tangent plane (terrain/earth_curvature.h); 0: flat world.
  double earth_radius_m = 0.0;

  glm::dvec3 forward() const;  // world direction of the view's centre ray
  glm::dvec3 right() const;
  glm::dvec3 up() const;

  // World (relative to the eye) -> GL view space (x right, y up, -z forward).
  glm::mat4 view_rotation() const;
  // Reversed-Z perspective for a [0, 1] clip depth range.
  glm::mat4 projection() const;
  glm::mat4 view_projection() const { return projection() * view_rotation(); }

  // Eye-relative view distance along the axis for a reversed-Z depth value.
  double depth_to_view_distance(float depth) const;
  // World direction through pixel centre (px, py), py = 0 at the top row.
  glm::dvec3 pixel_ray(double px, double py, int width, int height) const;
};

// Frustum planes in eye-relative world coordinates (a*x + b*y + c*z + d >= 0 inside).
struct Frustum {
  std::array<glm::dvec4, 6> planes;
  double earth_radius_m = 0.0;  // the camera's: boxes are lowered by the curvature drop
  // Conservative: false only when the box is entirely outside one plane.
  // Boxes are flat-terrain boxes (DEM heights); with curvature the box is
  // first lowered by the drop over its horizontal extent, as the shaders draw it.
  bool intersects_box(const glm::dvec3& lo, const glm::dvec3& hi) const;
};
Frustum frustum_of(const Camera& camera);

// The pixel rectangle (x0, y0, x1, y1 exclusive; GL window coordinates, y up)
// holding an eye-relative flat-terrain box as drawn (curvature as in
// Frustum::intersects_box); the whole viewport when a corner is near or
// behind the eye.
glm::ivec4 screen_rect_of_box(const Camera& camera, glm::dvec3 lo, glm::dvec3 hi, int width, int height);

}  // namespace ig::render
