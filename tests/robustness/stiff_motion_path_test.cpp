// Stiff motion through the scripted path (io/path_interpolator.h), then the
// two-level method's Level1 centre E over the same motions (bounds:
// robustness/stiff_motion_support.h).
#include <gtest/gtest.h>

#include "robustness/stiff_motion_support.h"

namespace {

using namespace stiff_motion;

// --------------------------------------------------------- scripted path --

// Keys of a motion every dt seconds; the path sampled at 240 Hz must stay in the envelope.
struct PathRun {
  std::vector<ig::io::Pose> poses;
  Envelope env;
  double worst_truth_pos = 0.0;
};

PathRun run_path(const Motion& m, double key_dt, double duration, double max_bulge_m) {
  ig::io::PathSpec spec;
  std::vector<Input> keys;
  for (double t = 0; t <= duration + 1e-9; t += key_dt) {
    const State s = m(t);
    ig::io::PathKey k;
    k.t_s = t;
    k.position = {s.pos.x, s.pos.y, s.pos.z};
    const auto hpr = ig::io::hpr_from_attitude(s.att);
    k.heading_deg = hpr.heading_deg;
    k.pitch_deg = hpr.pitch_deg;
    k.roll_deg = hpr.roll_deg;
    spec.keys.push_back(k);
    keys.push_back({t, s.pos, glm::dvec3(0.0), ig::io::attitude_from_hpr(hpr), 0.0});
  }
  const ig::io::PathInterpolator path(spec);
  PathRun r;
  for (double t = 0; t <= duration; t += 1.0 / 240) {
    const ig::io::Pose p = path.sample(t);
    r.poses.push_back(p);
    FilteredPose as_out;
    as_out.position = p.position;
    as_out.attitude = p.attitude;
    as_out.sample_time_s = t;
    // Catmull-Rom tangents are not the keys' velocities: check against the box grown by the stated bound.
    Envelope e;
    check_envelope(as_out, keys, 0.0, e);
    r.env.worst_pos_excess = std::max(r.env.worst_pos_excess, e.worst_pos_excess - max_bulge_m);
    r.env.worst_att_excess = std::max(r.env.worst_att_excess, e.worst_att_excess);
    r.worst_truth_pos = std::max(r.worst_truth_pos, glm::length(p.position - m(t).pos));
  }
  return r;
}

TEST(StiffMotionPath, Roll720KeysEvery30thOfASecond) {
  const PathRun r = run_path(roll_720(), 1.0 / 30, 2.0, 0.0);
  std::printf("[stiff] path 720 deg/s roll, keys 24 deg apart: envelope excess pos %.2e m att %.2e deg\n",
              r.env.worst_pos_excess, r.env.worst_att_excess * 180 / kPi);
  EXPECT_LT(r.env.worst_pos_excess, 1e-6);
  EXPECT_LT(r.env.worst_att_excess, 1e-7);
  for (size_t k = 1; k < r.poses.size(); ++k)
    EXPECT_GE(unwrap_step(roll_of(r.poses[k - 1].attitude), roll_of(r.poses[k].attitude)), -1e-6) << k;
}

TEST(StiffMotionPath, TenGPullUpKeysEveryTwentiethOfASecond) {
  // Catmull-Rom through keys 0.05 s apart on a 408 m circle: stated bound 5 cm outside the keys' box.
  const PathRun r = run_path(pull_up_10g(), 0.05, 8.0, 0.05);
  std::printf(
      "[stiff] path 10 g pull-up: envelope excess pos %.2e m (beyond 5 cm) att %.2e deg, off the circle %.4f m\n",
      r.env.worst_pos_excess, r.env.worst_att_excess * 180 / kPi, r.worst_truth_pos);
  EXPECT_LE(r.env.worst_pos_excess, 0.0);
  EXPECT_LT(r.env.worst_att_excess, 1e-7);
  EXPECT_LT(r.worst_truth_pos, 0.05);
}

TEST(StiffMotionPath, HeadingThroughNorthBothWays) {
  const PathRun r = run_path(heading_through_north(), 0.1, 8.0, 0.0);
  EXPECT_LT(r.env.worst_att_excess, 1e-7);
  for (size_t k = 1; k < r.poses.size(); ++k) {
    const double h0 = ig::io::hpr_from_attitude(r.poses[k - 1].attitude).heading_deg;
    const double h1 = ig::io::hpr_from_attitude(r.poses[k].attitude).heading_deg;
    EXPECT_LT(std::abs(unwrap_step(h0, h1)), 1.0) << "long way round at sample " << k;
    EXPECT_TRUE(h1 <= 60.01 || h1 >= 299.99) << h1;
  }
}

// ----------------------------------------------------- E over stiff motion --

// Renders the two-level method over poses; returns E's largest step within a
// mode (hit->hit or miss->miss) and at a switch, in metres.
struct ETrack {
  double within = 0.0, at_switch = 0.0;
  int switches = 0;
};

ETrack track_e(const std::vector<ig::render::Camera>& cams, const ig::terrain::Heightfield& hf) {
  robustness::Rig rig(hf, "twolevel", 80, 60);
  auto* tl = robustness::as_twolevel(rig.method());
  ETrack t;
  glm::dvec3 prev{0.0};
  bool prev_hit = false;
  for (size_t k = 0; k < cams.size(); ++k) {
    const auto f = rig.render(cams[k]);
    EXPECT_EQ(robustness::finite_problems(f), "") << "frame " << k;
    const auto& e = tl->look_at();
    if (k > 0) {
      const double step = glm::length(glm::dvec2(e.point - prev));
      if (e.hit == prev_hit) {
        t.within = std::max(t.within, step);
      } else {
        t.at_switch = std::max(t.at_switch, step);
        ++t.switches;
      }
    }
    prev = e.point;
    prev_hit = e.hit;
  }
  return t;
}

TEST(StiffMotionLevel1Centre, RollAboutTheViewAxisLeavesEPut) {
  const auto hf = robustness::hills();
  std::vector<ig::render::Camera> cams;
  for (int k = 0; k < 30; ++k)
    cams.push_back(robustness::camera_at({2000, 2500, hf.max_m + 100}, 40, -20, 720.0 * k / kRate, 60, 80, 60));
  const ETrack t = track_e(cams, hf);
  std::printf("[stiff] E under a 720 deg/s roll: largest step %.3f m\n", t.within);
  EXPECT_EQ(t.switches, 0);
  EXPECT_LT(t.within, 1e-6);
}

TEST(StiffMotionLevel1Centre, PullUpThroughTheHorizonHasNoExtraJump) {
  // 10 g pull-up from 5 degrees nose down, 60 Hz: the centre ray leaves the
  // terrain; E's step at that switch is no larger than its steps while hitting.
  const auto hf = robustness::hills();
  std::vector<ig::render::Camera> cams;
  const double w = 10.0 * kG / 200.0 * 180.0 / kPi;  // deg/s
  const glm::dvec3 eye(1500, 1500, hf.sample_surface(1500, 1500) + 80);
  for (int k = 0; k < 60; ++k) cams.push_back(robustness::camera_at(eye, 45, -5.0 + w * k / kRate, 0, 60, 80, 60));
  const ETrack up = track_e(cams, hf);
  std::reverse(cams.begin(), cams.end());
  const ETrack down = track_e(cams, hf);
  std::printf(
      "[stiff] E over a 10 g pull-up (%.1f deg/frame): largest step while hitting %.0f m, at the switch %.0f m "
      "(%d switches); pushing over: %.0f m, at the switch %.0f m (%d)\n",
      w / kRate, up.within, up.at_switch, up.switches, down.within, down.at_switch, down.switches);
  EXPECT_GE(up.switches, 1);
  EXPECT_GE(down.switches, 1);
  EXPECT_LE(up.at_switch, up.within + hf.spacing_x_m);
  EXPECT_LE(down.at_switch, down.within + hf.spacing_x_m);
}

}  // namespace
