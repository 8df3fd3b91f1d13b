#include "bench_variant_run.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "session/scenario_runner.h"
#include "session/view_step.h"
#include "stats/timing.h"

namespace ig::app {
namespace {

using stats::ms_since;
using stats::process_cpu_ms;

bool same_knob(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(b)); }

std::string label_of(const Variant& v, const render::TerrainMethod& m) {
  const auto k = m.knob();
  if (!k) return v.method;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", k->value);
  return v.method + " " + k->name + "=" + buf;
}

std::unique_ptr<render::TerrainMethod> build(const Variant& v, const BenchFlight& f, double& build_ms) {
  const auto t0 = Clock::now();
  auto method = render::make_method(v.method, *f.scene, f.shader_dir, f.method_options, v.knob);
  build_ms = ms_since(t0);
  return method;
}

}  // namespace

VariantRun::VariantRun(const Variant& variant, const BenchFlight& flight)
    : flight_(flight),
      variant_(variant),
      method_(build(variant, flight, row_.build_ms)),
      renderer_(std::make_unique<render::FrameRenderer>(*flight.scene, *method_, flight.shader_dir)),
      label_(label_of(variant, *method_)),
      knob_cell_(method_->knob() ? stats::Cell("knob", method_->knob()->value) : stats::Cell("knob", std::string())),
      samples_(flight.width, flight.height) {
  row_.method = variant.method;
  row_.knob = method_->knob();
  row_.default_knob = variant.is_default;
  spent_ms_ = row_.build_ms;
}

void VariantRun::warm_up() {
  const auto t0 = Clock::now();
  session::render_view(*flight_.scene, *renderer_, flight_.camera_at(flight_.frames.front()), *flight_.target);
  spent_ms_ += ms_since(t0);
}

void VariantRun::fly(int pos) {
  if (pos <= last_pos_) throw std::logic_error("VariantRun::fly: frame positions must increase");
  last_pos_ = pos;
  const auto t0 = Clock::now();
  render_and_compare(pos);
  spent_ms_ += ms_since(t0);
}

void VariantRun::render_and_compare(int pos) {
  const BenchFlight& f = flight_;
  const render::Camera camera = f.camera_at(f.frames[pos]);
  const auto t0 = Clock::now();
  const double cpu0 = process_cpu_ms();
  const render::ViewResult vr = session::render_view(*f.scene, *renderer_, camera, *f.target);
  const double cpu = process_cpu_ms() - cpu0;
  const double ms = ms_since(t0);
  frame_ms_.push_back(ms);
  cpu_ms_.push_back(cpu);
  cores_.push_back(ms > 0.0 ? cpu / ms : 0.0);
  hidden_.push_back(vr.method.column("hidden_boxes"));
  lod_ms_.push_back(vr.timings.lod_ms);
  triangles_.push_back(double(vr.method.triangles));
  vs_.push_back(double(vr.total.vs_invocations));
  fs_.push_back(double(vr.total.fs_invocations));
  passed_.push_back(double(vr.total.samples_passed) / (double(f.width) * f.height));
  prims_.push_back(double(vr.total.primitives));
  draws_.push_back(double(vr.total.draw_calls));
  uploads_.push_back(double(vr.total.bytes_uploaded));
  std::vector<stats::Cell> frame_row = {{"method", variant_.method},
                                        knob_cell_,
                                        {"frame", f.frames[pos]},
                                        {"frame_ms", ms},
                                        {"cpu_ms", cpu},
                                        {"lod_ms", vr.timings.lod_ms},
                                        {"terrain_ms", vr.timings.terrain_ms},
                                        {"sky_ms", vr.timings.sky_ms},
                                        {"clouds_ms", vr.timings.clouds_ms},
                                        {"triangles", vr.method.triangles},
                                        {"hidden_boxes", hidden_.back()}};
  session::append_work_columns(frame_row, vr, /*per_pass=*/false);
  f.frames_csv->add_row(frame_row);

  const bool sampled = next_sample_ < f.sample_pos.size() && f.sample_pos[next_sample_] == pos;
  if (!sampled && !f.before_pos.count(pos)) return;
  if (f.reference_camera.at(pos).position != camera.position)
    throw std::logic_error("reference and method cameras differ at frame " + std::to_string(f.frames[pos]));
  const stats::FrameImage img = stats::read_frame_image(*f.target);
  stats::LumaImage luma = stats::luminance(img);
  if (sampled) {
    ++next_sample_;
    std::optional<session::TemporalSample> pair;
    if (method_before_.count(pos - 1))
      pair = session::TemporalSample{
          f.frames[pos - 1], f.frames[pos] * f.time_step_s,
          stats::temporal_error(method_before_[pos - 1], luma, f.reference_luma.at(pos - 1), f.reference_luma.at(pos))};
    method_before_.erase(pos - 1);
    std::vector<stats::Cell> cells = {{"method", variant_.method}, knob_cell_, {"frame", f.frames[pos]}, {"frame_ms", ms}};
    for (auto& c : samples_.add(stats::image_error(img, f.reference.at(pos), camera),
                                method_->error_bound_px(camera, f.height), pair))
      cells.push_back(std::move(c));
    f.samples_csv->add_row(cells);
  }
  if (f.before_pos.count(pos)) method_before_[pos] = std::move(luma);
}

void VariantRun::fly_pipelined(int pos) {
  const BenchFlight& f = flight_;
  const auto t0 = Clock::now();
  renderer_->set_pipelined(true);
  // A frame waits only for the one kFramesInFlight before it.
  while (int(in_flight_.size()) >= kFramesInFlight) retire_done(true);
  const auto issued = Clock::now();
  const double cpu0 = process_cpu_ms();
  InFlight frame;
  frame.issued = issued;
  frame.frame = f.frames[pos];
  if (last_issue_) {
    frame.interval_ms = std::chrono::duration<double, std::milli>(issued - *last_issue_).count();
    frame.cpu_ms = cpu0 - last_issue_cpu_ms_;
  }
  last_issue_ = issued;
  last_issue_cpu_ms_ = cpu0;
  const render::ViewResult vr = session::render_view(*f.scene, *renderer_, f.camera_at(f.frames[pos]), *f.target);
  frame.lod_ms = vr.timings.lod_ms;
  frame.fence = gl::FrameFence::after_issued_work();
  in_flight_.push_back(std::move(frame));
  retire_done(false);
  renderer_->set_pipelined(false);
  spent_ms_ += ms_since(t0);
}

void VariantRun::end_pipelined() {
  const auto t0 = Clock::now();
  while (!in_flight_.empty()) retire_done(true);
  last_issue_.reset();
  spent_ms_ += ms_since(t0);
}

// Frames seen done leave the queue, oldest first; their latency is from
// being issued to being seen done (an upper bound: a frame is looked at
// after each issue and when the next must wait for it).
void VariantRun::retire_done(bool wait_oldest) {
  while (!in_flight_.empty()) {
    InFlight& f = in_flight_.front();
    if (wait_oldest) {
      f.fence.wait();
      wait_oldest = false;
    } else if (!f.fence.done()) {
      return;
    }
    const double latency = ms_since(f.issued);
    pipe_latency_ms_.push_back(latency);
    pipe_lod_ms_.push_back(f.lod_ms);
    if (f.interval_ms >= 0.0) {
      pipe_interval_ms_.push_back(f.interval_ms);
      pipe_cpu_ms_.push_back(f.cpu_ms);
    }
    if (flight_.pipelined_csv)
      flight_.pipelined_csv->add_row({{"method", variant_.method},
                                      knob_cell_,
                                      {"frame", f.frame},
                                      {"interval_ms", f.interval_ms},
                                      {"cpu_ms", f.cpu_ms},
                                      {"latency_ms", latency},
                                      {"lod_ms", f.lod_ms}});
    in_flight_.pop_front();
  }
}

session::BenchRow VariantRun::finish() {
  session::BenchRow row = row_;
  auto median = [](const std::vector<double>& v) { return stats::percentiles(v).median; };
  row.frames = int(frame_ms_.size());
  const auto frame_ms = stats::percentiles(frame_ms_);
  row.frame_ms_median = frame_ms.median;
  row.frame_ms_p95 = frame_ms.p95;
  row.lod_ms_median = median(lod_ms_);
  row.cpu_ms_median = median(cpu_ms_);
  row.cores_median = median(cores_);
  row.hidden_boxes_median = median(hidden_);
  row.triangles_median = median(triangles_);
  row.vs_invocations_median = median(vs_);
  row.fs_invocations_median = median(fs_);
  row.passed_per_pixel_median = median(passed_);
  row.primitives_median = median(prims_);
  row.draw_calls_median = median(draws_);
  row.upload_bytes_median = median(uploads_);
  if (!pipe_latency_ms_.empty()) {
    row.pipelined_frames = int(pipe_latency_ms_.size());
    const auto interval = stats::percentiles(pipe_interval_ms_);
    row.pipelined_frame_ms_median = interval.median;
    row.pipelined_frame_ms_p95 = interval.p95;
    row.pipelined_cpu_ms_median = median(pipe_cpu_ms_);
    row.pipelined_latency_ms_median = median(pipe_latency_ms_);
    row.pipelined_lod_ms_median = median(pipe_lod_ms_);
  }
  samples_.finish(row);
  return row;
}

std::vector<Variant> variants_for(const std::string& method, bool sweep, const render::MethodOptions& options) {
  const auto values = render::knob_sweep(method);
  if (!sweep || values.empty()) return {{method, std::nullopt, true}};
  // The default knob value, to mark it (and add it when the sweep lacks it).
  const auto knob = render::default_knob(method, options);
  std::vector<double> v = values;
  if (knob) {
    const double d = knob->value;
    if (std::none_of(v.begin(), v.end(), [&](double x) { return same_knob(x, d); })) {
      // Keep the sweep's order (least to most accurate) whichever way the knob runs.
      const bool ascending = v.back() >= v.front();
      auto pos = std::find_if(v.begin(), v.end(), [&](double x) { return ascending ? x > d : x < d; });
      v.insert(pos, d);
    }
  }
  std::vector<Variant> out;
  for (double x : v) out.push_back({method, x, knob && same_knob(x, knob->value)});
  return out;
}

}  // namespace ig::app
