#include "session/run_outputs.h"

#include "water/water_map.h"

#include <algorithm>
#include <cstdio>
#include <fstream>

#include "capture/png_writer.h"
#include "session/frametime_plot.h"
#include "session/process_memory.h"
#include "stats/timing.h"
#include "terrain/paged_heights.h"
#include "water/water_map.h"

namespace ig::session {
namespace {
using Clock = stats::WallClock;
using stats::ms_since;
std::string capture_name(const ChannelView& ch, int frame, double t) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "capture_%s_t%07.3fs_f%06d.png", ch.spec.name.c_str(), t, frame);
  return buf;
}
std::string final_name(const ChannelView& ch, size_t c) { return c == 0 ? "final.png" : "final_" + ch.spec.name + ".png"; }
}  // namespace

RunOutputs::RunOutputs(const std::filesystem::path& dir, std::string command, bool progress)
    : dir_((std::filesystem::create_directories(dir), dir)),
      command_(std::move(command)),
      progress_(progress),
      log_((dir / "frames.csv").string()),
      start_(Clock::now()),
      watch_(command_, [this](const std::string& line) { warn(line); }) {}

void RunOutputs::warn(const std::string& line) const {
  std::fprintf(stderr, "%s%s\n", progress_ && rendered_ > 0 ? "\n" : "", line.c_str());
}

void RunOutputs::frame(ScenarioRunner& runner, const FrameResult& f, bool capture, bool last, int total_frames,
                       const std::function<void(std::vector<stats::Cell>&)>& extra) {
  for (size_t c = 0; c < runner.channels().size(); ++c) {
    auto& ch = runner.channels()[c];
    double readback_ms = 0.0, present_ms = 0.0;
    if (capture || last) {
      const auto t0 = Clock::now();
      const auto rgba = ch.target->read_rgba();
      readback_ms = ms_since(t0);
      const int w = ch.target->width(), h = ch.target->height();
      std::vector<std::string> names;
      if (capture) names.push_back(capture_name(ch, f.frame, f.sim_time_s));
      if (last) names.push_back(final_name(ch, c));
      for (const auto& name : names) {
        capture::write_png_rgba((dir_ / name).string(), rgba, w, h);
        captured_.push_back(name);
      }
    }
    if (c == 0 && !runner.context().headless()) {
      const auto t0 = Clock::now();
      runner.present();
      present_ms = ms_since(t0);
    }
    add_pass_times(ch.last);
    auto row = frame_log_row(f, ch, readback_ms, present_ms);
    if (extra) extra(row);
    log_.add_row(row);
  }
  watch_.observe(runner, f);
  ++rendered_;
  final_written_ = final_written_ || last;
  if (f.page_waits > 0) ++frames_waited_on_io_;
  page_waits_ += std::max(f.page_waits, 0LL);
  page_ins_ += f.page_ins;
  if (f.imagery_held > 0) ++imagery_frames_held_;
  if (f.imagery_page_waits > 0) ++imagery_frames_waited_;
  imagery_held_ += std::max(f.imagery_held, 0LL);
  imagery_missing_ += f.imagery_missing;
  imagery_page_ins_ += f.imagery_page_ins;
  if (progress_) {
    const double elapsed = ms_since(start_) / 1000.0;
    if (total_frames > 0)
      std::fprintf(stderr, "\r%s: frame %d/%d  %.1f s elapsed, %.0f ms/frame   ", command_.c_str(), rendered_,
                   total_frames, elapsed, elapsed * 1000.0 / rendered_);
    else
      std::fprintf(stderr, "\r%s: frame %d  %.1f s elapsed, %.0f ms/frame   ", command_.c_str(), rendered_, elapsed,
                   elapsed * 1000.0 / rendered_);
  }
}

void RunOutputs::add_pass_times(const render::ViewResult& view) {
  for (const auto& p : view.passes) {
    if (p.ms < 0.0) continue;
    auto it = std::find_if(pass_ms_.begin(), pass_ms_.end(), [&](const auto& e) { return e.first == p.name; });
    if (it == pass_ms_.end()) it = pass_ms_.insert(pass_ms_.end(), {p.name, {}});
    it->second.push_back(p.ms);
  }
}

int RunOutputs::finish(ScenarioRunner& runner, const std::string& scenario_file, nlohmann::json extra) {
  if (progress_) std::fprintf(stderr, "\n");
  // A run that ended without a frame known to be its last (a host that
  // stopped sending, a signal): final.png is the last frame rendered.
  for (size_t c = 0; c < runner.channels().size() && rendered_ > 0 && !final_written_; ++c) {
    const auto& ch = runner.channels()[c];
    capture::write_png_rgba((dir_ / final_name(ch, c)).string(), ch.target->read_rgba(), ch.target->width(),
                            ch.target->height());
    captured_.push_back(final_name(ch, c));
  }
  const auto& s = runner.scenario();
  const auto& r = s.render;
  const auto& hf = runner.heightfield();
  nlohmann::json summary = {
      {"command", command_},
      {"scenario", s.name},
      {"scenario_file", scenario_file},
      {"method", r.method},
      {"width", r.width},
      {"height", r.height},
      {"channels", runner.channels().size()},
      {"frames_rendered", rendered_},
      {"time_step_s", s.time_step_s},
      {"gl_version", runner.context().gl_version()},
      {"gl_renderer", runner.context().gl_renderer()},
      {"shader_dir", runner.shader_dir()},
      {"headless", runner.context().headless()},
      {"antialiasing", r.antialiasing},
      {"msaa_samples", runner.channels().front().target->samples()},
      {"ground_detail", r.shading.ground_detail},
      {"deferred_shading", r.shading.deferred_shading},
      {"terrain",
       {{"source", hf.source},
        {"width", hf.width},
        {"height", hf.height},
        {"spacing_x_m", hf.spacing_x_m},
        {"spacing_y_m", hf.spacing_y_m},
        {"georeferenced", hf.georef.has_value()},
        {"load_ms", runner.load_ms()}}},
      {"frame_time", stats::frame_time_summary(log_.frame_ms(), r.frame_budget_ms)},
      {"captures", captured_},
      // Frames that drew sky only (pose over 1 km off the terrain, or no
      // terrain in any channel's view) and frames whose eye was underground.
      {"frames_outside_terrain", watch_.frames_outside()},
      {"frames_below_terrain", watch_.frames_below()},
      // At the last frame; azimuth clockwise from true north.
      {"sun_elevation_deg", runner.sun().elevation_deg},
      {"sun_azimuth_deg", runner.sun().azimuth_deg},
      {"visibility_m", runner.scene().shading().fog_visibility_m},  // 0: no fog
      {"process_memory", process_memory()},
  };
  // The water terrain.water found or read (none: null).
  summary["water"] = nullptr;
  if (hf.water) {
    double area = 0.0;
    for (const auto& b : hf.water->bodies()) area += b.area_m2;
    summary["water"] = {{"source", hf.water->source()},
                        {"bodies", hf.water->bodies().size()},
                        {"area_km2", area / 1e6}};
  }
  if (hf.paged) {  // paged heights
    const auto st = hf.paged->cache->stats();
    double wall_s = 0.0;
    for (double ms : log_.frame_ms()) wall_s += ms / 1000.0;
    summary["paging"] = {
        {"budget_mb", double(hf.paged->cache->budget_bytes()) / (1 << 20)},
        {"tile_samples", hf.paged->cache->tile_size()},
        {"resident_mb", double(st.resident_bytes) / (1 << 20)},
        {"peak_resident_mb", double(st.peak_resident_bytes) / (1 << 20)},
        {"pyramid_mb", double(hf.paged->pyramid->memory_bytes()) / (1 << 20)},
        {"frames_waited_on_io", frames_waited_on_io_},
        {"page_waits", page_waits_},
        // All page waits since the load, also outside frames (the first
        // window before frame 0, host queries between frames).
        {"page_waits_total", st.misses},
        {"page_ins", page_ins_},
        {"page_ins_per_s", wall_s > 0 ? double(page_ins_) / wall_s : 0.0},
        {"evictions", st.evictions},
        // Live (wait_for_pages false): reads a frame did not wait for (the
        // tile queued instead; Level1 kept its square: frames.csv level1_held).
        {"wait_for_pages", runner.scene().wait_for_pages()},
        {"deferred_reads", st.deferred},
    };
  }
  if (const render::ImageryWindowTexture* w = runner.scene().imagery_window()) {  // paged imagery
    const auto st = w->cache().stats();
    double wall_s = 0.0;
    for (double ms : log_.frame_ms()) wall_s += ms / 1000.0;
    summary["paging"]["imagery"] = {
        {"budget_mb", double(w->cache().budget_bytes()) / (1 << 20)},
        {"tile_pixels", w->cache().tile_size()},
        {"full_size", {w->full_size().x, w->full_size().y}},
        {"window", w->size().x},
        {"resident_mb", double(st.resident_bytes) / (1 << 20)},
        {"peak_resident_mb", double(st.peak_resident_bytes) / (1 << 20)},
        {"moves", w->stats().moves},
        {"held_moves", imagery_held_},
        {"frames_held", imagery_frames_held_},
        {"missing_tiles", imagery_missing_},
        {"frames_waited_on_io", imagery_frames_waited_},
        {"page_waits_total", st.misses},  // incl. the first fill at load
        {"page_ins", imagery_page_ins_},
        {"page_ins_per_s", wall_s > 0 ? double(imagery_page_ins_) / wall_s : 0.0},
        {"evictions", st.evictions},
        {"failed_tiles", w->failed_tiles()},
    };
  }
  std::string pass_line;
  for (const auto& [name, ms] : pass_ms_) {
    const double median = stats::percentiles(ms).median;
    summary["pass_ms_median"][name] = median;
    char buf[96];
    std::snprintf(buf, sizeof buf, "%s%s %.2f", pass_line.empty() ? "" : ", ", name.c_str(), median);
    pass_line += buf;
  }
  if (extra.is_object() && extra.contains("pose_intake"))  // where ig serve has always reported it
    extra["pose_intake"]["frames_outside_terrain"] = watch_.frames_outside();
  for (auto it = extra.begin(); extra.is_object() && it != extra.end(); ++it) summary[it.key()] = it.value();
  std::ofstream((dir_ / "summary.json").string()) << summary.dump(2) << "\n";
  const bool plotted = plot_frame_times(log_.path(), (dir_ / "frametime.png").string(),
                                        s.name + " / " + r.method + " / " + runner.context().gl_renderer(),
                                        r.frame_budget_ms);
  const auto& ft = summary["frame_time"];
  std::printf("%s: %s, %d frames x %zu channel(s) at %dx%d, method %s on %s: median %.1f ms, p95 %.1f ms\n",
              command_.c_str(), s.name.c_str(), rendered_, runner.channels().size(), r.width, r.height,
              r.method.c_str(), runner.context().gl_renderer().c_str(), ft["median_ms"].get<double>(),
              ft["p95_ms"].get<double>());
  std::printf("%s: outputs in %s (frames.csv, summary.json, %zu PNG%s%s)\n", command_.c_str(), dir_.string().c_str(),
              captured_.size(), captured_.size() == 1 ? "" : "s", plotted ? ", frametime.png" : "");
  if (!pass_line.empty())
    std::printf("%s: median ms per pass, each finished before the next (--pass-times): %s\n", command_.c_str(),
                pass_line.c_str());
  return plotted ? 0 : 1;
}

}  // namespace ig::session
