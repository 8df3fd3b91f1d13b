#pragma once
// Constants the pose filter's intake (pose_filter.cpp) and output
// (pose_filter_sample.cpp) sides share.

namespace ig::io::pose_filter_detail {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegToRad = kPi / 180.0;
// Consecutive samples further apart than this are not differenced for
// extrapolation rates or used for the packet interval estimate.
constexpr double kMaxDiffGapS = 0.5;

}  // namespace ig::io::pose_filter_detail
