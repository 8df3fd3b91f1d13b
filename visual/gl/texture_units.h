#pragma once
// The one table of texture units. Every sampler a program reads is bound to
// its own unit here, so no two passes can pick the same unit for different
// textures (the shaders' sampler uniforms are set from these values).

namespace ig::gl {

enum class TextureUnit : int {
  kHeight = 0,          // the scene's height texture (whole DEM or its overview)
  kImagery = 1,         // draped imagery (or its overview)
  kBetaTemplate = 2,    // two-level: the band's weight template
  kBandColor = 3,       // two-level: the band target's uv, beta and mask
  kBandDepth = 4,       // two-level: the band target's depth
  kHeightWindow = 5,    // full-resolution heights around Level1
  kImageryWindow = 6,   // full-resolution imagery around Level1
  kGroundDetail = 7,    // the ground-detail noise
  kFrameColor = 8,      // a full-screen pass's source: the drawn frame (post filter, coverage count)
  kSurface = 9,         // deferred shading: each pixel's surface coordinate and distance
  kFootprint = 10,      // deferred shading: the coordinate's screen derivatives
  kHeightDifferences = 11,  // each sample's central differences of height (the shading's normal)
  kWaterShare = 12,     // the share of water around each sample (scenes with water)
  kWaves = 13,          // the water's wave slopes (scenes with water)
  kWaterMarks = 14,     // deferred shading's marks of where water may be (the water pass's mask)
  kWaterPresence = 15,  // where water may be, coarsely (scenes with water)
  kEntityBaseColor = 16,  // an entity model's base colour texture (scenes with entities)
  kFrameDepth = 17,     // a full-screen pass's view of the frame's depth (the clouds)
  kCloudNoise = 18,     // the field the cloud layers are cut from (scenes with clouds)
  kCloudLight = 19,     // the clouds marched at half resolution: light and the share that shows
  kCloudDepth = 20,     // the depth each of those was marched to
};

constexpr int unit(TextureUnit u) { return static_cast<int>(u); }

}  // namespace ig::gl
