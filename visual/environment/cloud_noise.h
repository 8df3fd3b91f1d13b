#pragma once
// The field every cloud layer is cut from: a tileable square of fractal
// value noise whose values are ranked, so they are spread evenly over
// [0, 1). A layer of coverage c is cloud where the field exceeds 1 - c, so
// the share of sky it covers is c by construction, not by tuning. The
// octaves stop at a period of kCloudNoiseLowestPeriod texels: no coarser
// variation, so any patch a few elements wide has close to the layer's
// coverage too. No GL (gl/cloud_pass uploads it).

#include <cstdint>
#include <vector>

namespace ig::environment {

constexpr int kCloudNoiseSide = 256;          // texels a side; the field repeats after it
constexpr int kCloudNoiseLowestPeriod = 32;   // texels: the coarsest octave's lattice period
// Texels across one cloud element (half the coarsest period): the cloud
// pass scales a type's element size (cloud_layers.h) by it.
constexpr double kCloudNoiseElementTexels = 16.0;

// side x side values in [0, 1), row-major, tileable in both axes, each
// value distinct (ranks) so a threshold t leaves exactly (1 - t) of them above.
std::vector<float> cloud_noise_field(std::uint32_t seed = 1, int side = kCloudNoiseSide);

}  // namespace ig::environment
