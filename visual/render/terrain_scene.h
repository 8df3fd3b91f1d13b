#pragma once
// GPU-side terrain shared by every LOD method: the height texture, optional
// imagery, the shading parameters and the shading program's common uniforms.
// Methods own only their geometry and selection, so all of them shade alike.
//
// Height texture: R32F. Every int16 DEM height is exact in float32 and a
// float32 DEM keeps its own precision (24-bit mantissa: < 0.5 mm at 8848 m);
// R16 with scale/offset would quantise float DEMs (e.g. 0.07 m steps over a
// 4400 m range) for half the memory (4097^2: 64 MiB vs 32 MiB).
//
// Where the terrain sits: world_origin is the world position (double) of
// sample (0, 0) at height 0; methods work in terrain-local metres, and the
// FrameRenderer hands them local_camera(world camera), so an eye 1e7 m from
// the world origin is as precise as one at the origin. Earth curvature
// (terrain/earth_curvature.h) is a property of the scene too; it travels to
// the methods in Camera::earth_radius_m (culling) and to every terrain vertex
// shader through bind_common (u_earth_radius_m).

#include <epoxy/gl.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include <glm/vec3.hpp>

#include "gl/gl_objects.h"
#include "gl/shader_program.h"
#include "options/shading_options.h"
#include "render/camera.h"
#include "terrain/height_pyramid.h"
#include "terrain/heightfield.h"

namespace ig::render {

using ShadingParams = options::ShadingOptions;  // options/shading_options.h

class TerrainScene {
 public:
  // Uploads the height texture (and imagery, only when given). Throws
  // std::invalid_argument for a heightfield with fewer than 2 x 2 samples
  // (no surface to draw).
  TerrainScene(const terrain::Heightfield& heightfield, const ShadingParams& shading,
               const std::optional<std::string>& imagery_path = std::nullopt);
  TerrainScene(const TerrainScene&) = delete;
  TerrainScene& operator=(const TerrainScene&) = delete;

  const terrain::Heightfield& heightfield() const { return heightfield_; }
  const ShadingParams& shading() const { return shading_; }
  // Fog visibility in metres (0 = no fog); used from the next bind_common.
  void set_fog_visibility(double metres) { shading_.fog_visibility_m = metres; }
  GLuint height_texture() const { return height_tex_.id(); }
  bool has_imagery() const { return bool(imagery_tex_); }
  double upload_ms() const { return upload_ms_; }
  // Imagery texels of the DEM's footprint the image did not cover (grey).
  std::int64_t imagery_uncovered() const { return imagery_uncovered_; }
  // The min/max pyramid of the heightfield (ray casts, culling bounds),
  // built on first use and shared by every method and channel on this scene:
  // it is view-independent and large (180 MB for a 4097^2 DEM).
  const terrain::HeightPyramid& height_pyramid() const;

  // World position of sample (0, 0) at height 0 (default: the origin).
  const glm::dvec3& world_origin() const { return world_origin_; }
  void set_world_origin(const glm::dvec3& origin) { world_origin_ = origin; }
  // Sphere radius for the curvature drop; 0 = flat (default). Non-finite or
  // negative values mean flat.
  double earth_radius_m() const { return earth_radius_m_; }
  void set_earth_radius(double metres) { earth_radius_m_ = metres > 0.0 && std::isfinite(metres) ? metres : 0.0; }
  // The camera methods see: position relative to sample (0, 0) (computed in
  // double), earth_radius_m set from the scene.
  Camera local_camera(const Camera& world) const;

  // Binds the textures and sets the uniforms every terrain program shares
  // (see shaders/terrain.frag and terrain_grid.vert), u_earth_radius_m from
  // the (local) camera.
  void bind_common(const gl::ShaderProgram& program, const Camera& camera) const;

 private:
  const terrain::Heightfield& heightfield_;
  ShadingParams shading_;
  gl::Texture height_tex_;
  gl::Texture imagery_tex_;  // empty without imagery
  double upload_ms_ = 0.0;
  std::int64_t imagery_uncovered_ = 0;
  mutable std::unique_ptr<terrain::HeightPyramid> pyramid_;  // see height_pyramid()
  glm::dvec3 world_origin_{0.0};
  double earth_radius_m_ = 0.0;
};

}  // namespace ig::render
