#include "environment/cloud_frame.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat2x2.hpp>

#include "environment/cloud_noise.h"

namespace ig::environment {
namespace {

double wrap(double v) { return v - std::floor(v); }

constexpr double kHeapFootprintPower = 1.2;

// Metres -> noise coordinates: elements `streak` times longer along the wind.
glm::dmat2 noise_axes(const options::CloudLayer& l, const CloudLook& look) {
  const double tile_m = look.element_m / kCloudNoiseElementTexels * kCloudNoiseSide;
  const double speed = glm::length(l.wind_mps);
  const glm::dvec2 along = speed > 0.0 ? l.wind_mps / speed : glm::dvec2(1.0, 0.0);
  const glm::dvec2 across(-along.y, along.x);
  // Rows project onto the axes (column-major: columns are the matrix's columns).
  glm::dmat2 m(along.x / look.streak, across.x, along.y / look.streak, across.y);
  return m / tile_m;
}

}  // namespace

CloudFrame cloud_frame(const options::CloudLayers& layers, const glm::dvec3& eye, double time_s, const SkyLight& sky) {
  CloudFrame f;
  for (const auto& l : layers) {
    if (f.layers == kMaxCloudLayers) break;
    if (l.coverage <= 0.0 || l.thickness_m <= 0.0) continue;
    const CloudLook look = look_of(l.type);
    const double texel_m = look.element_m / kCloudNoiseElementTexels;
    const double top = l.base_m + l.thickness_m;
    const int form = look.form == CloudForm::Stratiform ? 0 : look.form == CloudForm::Cumuliform ? 1 : 2;
    // Steps through each stretch of a layer the ray crosses: heaps change
    // shape along the ray, decks only with their coverage, veils are thin.
    const double steps = form == 1 ? 16.0 : form == 0 ? 10.0 : 6.0;
    // The field is ranked (uniform), so cutting it at 1 - c leaves c of it
    // cloud. Coverage is the share of sky an observer sees hidden, and heaps
    // hide sky with their sides too: their footprints cover c^1.2 (fitted to
    // the sky hidden straight up at 25 % and 50 %: docs/rendering.md).
    const double footprint = form == 1 ? std::pow(l.coverage, kHeapFootprintPower) : l.coverage;
    const double threshold = l.coverage >= 1.0 ? -1.0 : 1.0 - footprint;
    const glm::dmat2 axes = noise_axes(l, look);
    // Each layer id its own part of the field, so stacked layers do not line up.
    const glm::dvec2 seed_offset(0.37 * l.id, 0.61 * l.id);
    const glm::dvec2 at = axes * (glm::dvec2(eye) - l.wind_mps * time_s) + seed_offset;
    glm::vec4* p = &f.packed[std::size_t(4 * f.layers)];
    p[0] = glm::vec4(float(l.base_m), float(top), float(l.transition_m), float(extinction_per_m(l)));
    p[1] = glm::vec4(float(threshold), float(form), float(steps), float(texel_m));
    p[2] = glm::vec4(float(wrap(at.x)), float(wrap(at.y)), 0.0f, 0.0f);
    p[3] = glm::vec4(float(axes[0][0]), float(axes[0][1]), float(axes[1][0]), float(axes[1][1]));
    ++f.layers;
  }
  f.sun_direction = sky.sun_direction;
  f.sun_light = sky.sun_light;
  // The sky's light on a cloud: from the whole upper hemisphere on its top,
  // less under it (the ground below reflects little).
  f.sky_light_top = sky.ambient * 2.0f;
  f.sky_light_base = sky.ambient * 1.2f;
  const float ground = sky.ground_light();
  f.shadow_floor = ground > 0.0f ? std::clamp(luma(sky.ambient) / ground, 0.0f, 1.0f) : 1.0f;
  return f;
}

}  // namespace ig::environment
