#include "session/bench_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "session/gnuplot.h"

namespace ig::session {
namespace {

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}
std::string num(double v) { return fmt("%.6g", v); }
std::string opt(const std::optional<double>& v, const char* f = "%.6g") { return v ? fmt(f, *v) : ""; }

// Methods in the order they first appear, each with its rows in sweep order.
std::vector<std::pair<std::string, std::vector<const BenchRow*>>> by_method(const std::vector<BenchRow>& rows) {
  std::vector<std::pair<std::string, std::vector<const BenchRow*>>> out;
  for (const auto& r : rows) {
    auto it = std::find_if(out.begin(), out.end(), [&](const auto& p) { return p.first == r.method; });
    if (it == out.end()) out.push_back({r.method, {&r}});
    else it->second.push_back(&r);
  }
  return out;
}

// A Markdown table row: "| a | b |".
void table_row(std::ostream& o, const std::vector<std::string>& cells) {
  for (const auto& c : cells) o << "| " << c << " ";
  o << "|\n";
}

// A Markdown table's header: the column names and the rule under them.
void table_header(std::ostream& o, const std::vector<std::string>& columns) {
  table_row(o, columns);
  for (size_t k = 0; k < columns.size(); ++k) o << "|---";
  o << "|\n";
}

std::string knob_text(const BenchRow& r) {
  if (!r.knob) return "-";
  return r.knob->name + "=" + num(r.knob->value) + (r.default_knob ? " (default)" : "");
}

// Time at `target` along one method's curve (rows in sweep order).
MatchedRow match_one(const std::string& method, const std::vector<const BenchRow*>& pts, double target,
                     double BenchRow::*time) {
  MatchedRow m;
  m.method = method;
  const double eps = 1e-9 * std::max(1.0, std::abs(target));
  // A point at the target gives its own time (the default target is the
  // two-level default's own error); otherwise interpolate between neighbours.
  std::optional<double> best;
  for (const BenchRow* p : pts)
    if (std::abs(p->horizon_mean_px - target) <= eps) best = std::min(best.value_or(p->*time), p->*time);
  const bool exact = best.has_value();
  for (size_t k = 0; !exact && k + 1 < pts.size(); ++k) {
    const double e0 = pts[k]->horizon_mean_px, e1 = pts[k + 1]->horizon_mean_px;
    const double t0 = pts[k]->*time, t1 = pts[k + 1]->*time;
    if (target < std::min(e0, e1) - eps || target > std::max(e0, e1) + eps) continue;
    const double ms = std::abs(e1 - e0) <= eps ? std::min(t0, t1) : t0 + (target - e0) / (e1 - e0) * (t1 - t0);
    best = std::min(best.value_or(ms), ms);
  }
  if (best) {
    m.kind = exact ? MatchKind::Measured : MatchKind::Interpolated;
    m.frame_ms = *best;
    return m;
  }
  const bool all_below = std::all_of(pts.begin(), pts.end(), [&](const BenchRow* p) { return p->horizon_mean_px < target; });
  if (all_below) {
    m.kind = MatchKind::AtMost;
    m.frame_ms = (*std::min_element(pts.begin(), pts.end(), [time](auto a, auto b) {
                   return a->*time < b->*time;
                 }))->*time;
  } else {
    m.kind = MatchKind::NotReached;
    m.frame_ms = (*std::min_element(pts.begin(), pts.end(), [time](auto a, auto b) {
                   return a->horizon_mean_px < b->horizon_mean_px;
                 }))->*time;
  }
  return m;
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string matched_ms_text(const MatchedRow& m) {
  const std::string v = fmt("%.2f", m.frame_ms);
  switch (m.kind) {
    case MatchKind::Measured:
    case MatchKind::Interpolated: return v;
    case MatchKind::AtMost: return "<= " + v;
    case MatchKind::NotReached: return "> " + v;
  }
  return v;
}

// gnuplot's default colours repeat after a few curves: one colour and point
// shape per method so seven curves stay apart (the same in every plot).
constexpr const char* kColours[] = {"#d62728", "#7f7f7f", "#1f77b4", "#2ca02c",
                                    "#ff7f0e", "#9467bd", "#17becf", "#8c564b"};
constexpr int kPoints[] = {7, 6, 5, 9, 11, 13, 4, 8};

std::string how_text(MatchKind k) {
  switch (k) {
    case MatchKind::Measured: return "measured at the target";
    case MatchKind::Interpolated: return "interpolated on its sweep";
    case MatchKind::AtMost: return "every point is more accurate: its cheapest point";
    case MatchKind::NotReached: return "never that accurate: its most accurate point";
  }
  return "";
}

}  // namespace

std::vector<MatchedRow> match_horizon_error(const std::vector<BenchRow>& rows, double target_px,
                                            double BenchRow::*time) {
  std::vector<MatchedRow> out;
  for (const auto& [method, pts] : by_method(rows)) out.push_back(match_one(method, pts, target_px, time));
  const auto tl = std::find_if(out.begin(), out.end(), [](const MatchedRow& m) { return m.method == "twolevel"; });
  if (tl != out.end() && (tl->kind == MatchKind::Measured || tl->kind == MatchKind::Interpolated) &&
      tl->frame_ms > 0.0)
    for (auto& m : out) m.ratio = m.frame_ms / tl->frame_ms;
  return out;
}

void write_bench_csv(const std::string& path, const std::vector<BenchRow>& rows) {
  std::ofstream o(path);
  if (!o) throw std::runtime_error(path + ": cannot create");
  o << "method,knob_name,knob_value,knob_unit,is_default,build_ms,frames,frame_ms_median,frame_ms_p95,"
       "lod_ms_median,triangles_median,error_samples,horizon_mean_px,horizon_max_px,depth_rel_p95,"
       "depth_rel_max,psnr_db,holes_mean,hole_fraction,interior_holes_mean,enclosed_holes_mean,bound_px_median,"
       "bound_px_max,vs_invocations_median,fs_invocations_median,primitives_median,draw_calls_median,"
       "upload_bytes_median,cpu_ms_median,temporal_pairs,temporal_error_mean,temporal_error_max,cores_median,"
       "hidden_boxes_median,passed_per_pixel_median,pipelined_frames,pipelined_frame_ms_median,"
       "pipelined_frame_ms_p95,pipelined_cpu_ms_median,pipelined_latency_ms_median,pipelined_lod_ms_median\n";
  for (const auto& r : rows) {
    o << csv_field(r.method) << ',' << (r.knob ? csv_field(r.knob->name) : "") << ','
      << (r.knob ? num(r.knob->value) : "") << ',' << (r.knob ? csv_field(r.knob->unit) : "") << ','
      << (r.default_knob ? 1 : 0) << ',' << fmt("%.3f", r.build_ms) << ',' << r.frames << ','
      << fmt("%.4f", r.frame_ms_median) << ',' << fmt("%.4f", r.frame_ms_p95) << ',' << fmt("%.4f", r.lod_ms_median)
      << ',' << fmt("%.10g", r.triangles_median) << ',' << r.error_samples << ',' << num(r.horizon_mean_px) << ','
      << num(r.horizon_max_px) << ',' << num(r.depth_rel_p95) << ',' << num(r.depth_rel_max) << ','
      << num(r.psnr_db) << ',' << num(r.holes_mean) << ',' << num(r.hole_fraction) << ','
      << num(r.interior_holes_mean) << ',' << num(r.enclosed_holes_mean) << ',' << opt(r.bound_px_median) << ','
      << opt(r.bound_px_max) << ',' << fmt("%.10g", r.vs_invocations_median) << ','
      << fmt("%.10g", r.fs_invocations_median) << ',' << fmt("%.10g", r.primitives_median) << ','
      << fmt("%.10g", r.draw_calls_median) << ',' << fmt("%.10g", r.upload_bytes_median) << ','
      << fmt("%.4f", r.cpu_ms_median) << ',' << r.temporal_pairs << ',' << num(r.temporal_error_mean) << ','
      << num(r.temporal_error_max) << ',' << fmt("%.3f", r.cores_median) << ','
      << fmt("%.10g", r.hidden_boxes_median) << ',' << fmt("%.4f", r.passed_per_pixel_median) << ','
      << r.pipelined_frames << ',' << fmt("%.4f", r.pipelined_frame_ms_median) << ','
      << fmt("%.4f", r.pipelined_frame_ms_p95) << ',' << fmt("%.4f", r.pipelined_cpu_ms_median) << ','
      << fmt("%.4f", r.pipelined_latency_ms_median) << ',' << fmt("%.4f", r.pipelined_lod_ms_median) << '\n';
  }
}

namespace {
// Each row flown finished and pipelined, side by side.
void write_pipelined(std::ostream& o, const std::vector<BenchRow>& rows) {
  o << "\n## Pipelined: frames in flight\n\n"
    << "The same frames flown again, each issued while the one before is still drawn (at most "
       "2 in flight), in stretches of 10 consecutive frames taken in turn by every method and knob, as a live "
       "IG runs: no stage waits for the GPU, no pipeline statistics are read. Frame ms: from one frame's issue "
       "to the next one's (what the IG sustains); finished / pipelined: what the overlap buys; CPU ms over "
       "the same interval; latency: from a frame's issue to its being seen done (an upper bound); LOD ms: "
       "the LOD step, now sharing the CPU with the frame before.\n\n";
  table_header(o, {"method", "knob", "finished frame ms", "pipelined frame ms median", "p95", "fps",
                   "finished / pipelined", "CPU ms", "latency ms", "LOD ms"});
  for (const auto& r : rows)
    table_row(o, {r.method, knob_text(r), fmt("%.2f", r.frame_ms_median), fmt("%.2f", r.pipelined_frame_ms_median),
                  fmt("%.2f", r.pipelined_frame_ms_p95),
                  fmt("%.1f", r.pipelined_frame_ms_median > 0 ? 1000.0 / r.pipelined_frame_ms_median : 0.0),
                  fmt("%.2f", r.pipelined_frame_ms_median > 0 ? r.frame_ms_median / r.pipelined_frame_ms_median : 0.0),
                  fmt("%.2f", r.pipelined_cpu_ms_median), fmt("%.2f", r.pipelined_latency_ms_median),
                  fmt("%.3f", r.pipelined_lod_ms_median)});
}
}  // namespace

void write_bench_markdown(const std::string& path, const BenchContext& c, const std::vector<BenchRow>& rows,
                          std::optional<double> target_px, const std::string& target_source) {
  std::ofstream o(path);
  if (!o) throw std::runtime_error(path + ": cannot create");
  auto list = [](const std::vector<int>& v) {
    std::string s;
    for (size_t k = 0; k < v.size(); ++k) s += (k ? ", " : "") + std::to_string(v[k]);
    return s;
  };
  o << "# ig bench: " << c.scenario_name << "\n\n"
    << "- command: `" << c.command_line << "`\n"
    << "- scenario: `" << c.scenario_file << "`\n"
    << "- renderer: " << c.gl_renderer << " (" << c.gl_version << ")\n"
    << "- machine: " << c.cpu << ", host " << c.host << "\n"
    << "- terrain: " << c.terrain << "\n"
    << "- image: " << c.width << "x" << c.height << ", vertical FOV " << num(c.fov_y_deg) << " deg\n"
    << "- frames: " << c.frames << " of the scenario's " << c.scenario_frames << " (time step "
    << num(c.time_step_s) << " s" << (c.frames < c.scenario_frames ? ", spread evenly over the flight" : "")
    << "), one untimed warm-up frame per method, "
    << (c.interleaved ? "interleaved (each frame flown by every method and knob in turn, the first of them rotating)"
                      : "one method and knob after the other")
    << "\n"
    << "- image error: " << c.sample_indices.size() << " sampled frames (scenario frames " << list(c.sample_indices)
    << ") against the reference renderer with the same camera\n"
    << "- temporal error: " << c.temporal_before_indices.size()
    << " pairs, each sampled frame with the frame rendered just before it (scenario frames "
    << list(c.temporal_before_indices) << "), against the reference's change between the same cameras\n"
    << "- knobs: " << (c.sweep ? "each method's sweep (knob_sweep) plus its default" : "each method's default")
    << "\n"
    << "- wall time of the whole run: " << fmt("%.1f", c.wall_s) << " s\n\n";

  o << "## Error against run time\n\n"
    << "Frame time: LOD update + passes + sky, closed with glFinish (wall clock), median and p95 over the frames. "
       "Errors over the sampled frames; temporal error (popping, luma levels) over the pairs (frame rendered "
       "just before a sample, the sample). Column definitions: docs/bench.md.\n\n";
  table_header(o, {"method", "knob", "frame ms median", "p95", "fps", "LOD ms", "triangles", "horizon mean px",
                   "horizon max px", "depth p95", "depth max", "PSNR dB", "holes/frame", "bound px median / max",
                   "temporal error mean / max"});
  for (const auto& r : rows)
    table_row(o, {r.method, knob_text(r), fmt("%.2f", r.frame_ms_median), fmt("%.2f", r.frame_ms_p95),
                  fmt("%.1f", r.frame_ms_median > 0 ? 1000.0 / r.frame_ms_median : 0.0), fmt("%.3f", r.lod_ms_median),
                  fmt("%.0f", r.triangles_median), fmt("%.3f", r.horizon_mean_px), fmt("%.0f", r.horizon_max_px),
                  fmt("%.5f", r.depth_rel_p95), fmt("%.4f", r.depth_rel_max), fmt("%.2f", r.psnr_db),
                  fmt("%.1f", r.holes_mean),
                  r.bound_px_median ? fmt("%.2f", *r.bound_px_median) + " / " + fmt("%.2f", *r.bound_px_max) : "none",
                  r.temporal_pairs ? fmt("%.3f", r.temporal_error_mean) + " / " + fmt("%.3f", r.temporal_error_max)
                                   : "none"});

  o << "\n## Work per frame\n\n"
    << "Hardware-independent work, medians over the frames: vertex and fragment shader invocations and "
       "primitives submitted (pipeline statistics queries, every pass including the sky), draw calls, bytes "
       "uploaded to the GPU; process CPU time per frame (every thread, llvmpipe's included: what the frame "
       "costs in CPU work, unlike the wall clock barely changed by other load on the machine); cores: CPU time / "
       "wall time per frame; hidden boxes: pieces horizon culling left out per frame; passed / px: samples "
       "that passed the depth test per pixel, every pass (what an early-z GPU shades). docs/bench.md.\n\n";
  table_header(o, {"method", "knob", "vertex invocations", "fragment invocations", "primitives", "draw calls",
                   "bytes uploaded", "CPU ms", "cores", "hidden boxes", "passed / px"});
  for (const auto& r : rows)
    table_row(o, {r.method, knob_text(r), fmt("%.0f", r.vs_invocations_median), fmt("%.0f", r.fs_invocations_median),
                  fmt("%.0f", r.primitives_median), fmt("%.0f", r.draw_calls_median),
                  fmt("%.0f", r.upload_bytes_median), fmt("%.2f", r.cpu_ms_median), fmt("%.2f", r.cores_median),
                  fmt("%.0f", r.hidden_boxes_median), fmt("%.2f", r.passed_per_pixel_median)});

  if (c.pipelined) write_pipelined(o, rows);

  o << "\n## Matched horizon error\n\n";
  if (!target_px) {
    o << "No target: the run has no twolevel row and no --match-px.\n";
    return;
  }
  o << "Target: mean horizon error " << fmt("%.3f", *target_px) << " px (" << target_source
    << "). Each method's median frame time at that error: a point at the target gives its own time, else "
       "linear interpolation between neighbouring points of its sweep (docs/bench.md); ratio = method ms / "
       "twolevel ms (how many times faster the two-level method is at equal horizon error).\n\n";
  table_header(o, {"method", "frame ms at target", "how", "ratio vs twolevel", "CPU ms at target", "CPU ratio",
                   "temporal error at target"});
  auto ratio_text = [](const MatchedRow& m) {
    if (!m.ratio) return std::string("n/a (no twolevel time at the target)");
    const std::string v = fmt("%.2f", *m.ratio);
    return m.kind == MatchKind::AtMost ? "<= " + v : m.kind == MatchKind::NotReached ? "> " + v : v;
  };
  const auto wall = match_horizon_error(rows, *target_px);
  const auto cpu = match_horizon_error(rows, *target_px, &BenchRow::cpu_ms_median);
  // Popping at equal accuracy: the temporal error interpolated the same way;
  // beyond a method's sweep it is not known.
  const auto temporal = match_horizon_error(rows, *target_px, &BenchRow::temporal_error_mean);
  auto temporal_text = [](const MatchedRow& m) {
    return m.kind == MatchKind::Measured || m.kind == MatchKind::Interpolated ? fmt("%.3f", m.frame_ms)
                                                                              : std::string("n/a (outside its sweep)");
  };
  for (size_t k = 0; k < wall.size(); ++k)
    table_row(o, {wall[k].method, matched_ms_text(wall[k]), how_text(wall[k].kind), ratio_text(wall[k]),
                  matched_ms_text(cpu[k]), ratio_text(cpu[k]), temporal_text(temporal[k])});

  if (c.pipelined) {
    o << "\nPipelined (frames in flight): each method's frame interval and CPU time per frame at the target, "
         "matched the same way; ratio = method / twolevel.\n\n";
    table_header(o, {"method", "pipelined frame ms at target", "ratio vs twolevel", "CPU ms at target", "CPU ratio"});
    const auto pipe = match_horizon_error(rows, *target_px, &BenchRow::pipelined_frame_ms_median);
    const auto pipe_cpu = match_horizon_error(rows, *target_px, &BenchRow::pipelined_cpu_ms_median);
    for (size_t k = 0; k < pipe.size(); ++k)
      table_row(o, {pipe[k].method, matched_ms_text(pipe[k]), ratio_text(pipe[k]), matched_ms_text(pipe_cpu[k]),
                    ratio_text(pipe_cpu[k])});
  }

  // The same comparison at every two-level setting of a sweep, on CPU time.
  std::vector<const BenchRow*> settings;
  for (const auto& r : rows)
    if (r.method == "twolevel") settings.push_back(&r);
  if (settings.size() < 2) return;
  o << "\n## Matched horizon error at every two-level setting\n\n"
    << "CPU ms of each method at that setting's mean horizon error (matched as above) / the setting's own CPU ms "
       "(> 1: two-level is faster; \"<=\" and \">\" as above).\n\n| two-level setting | horizon px | CPU ms |";
  const auto header = match_horizon_error(rows, settings.front()->horizon_mean_px, &BenchRow::cpu_ms_median);
  auto baseline = [](const MatchedRow& m) { return m.method != "twolevel" && m.method != "reference"; };
  int columns = 0;
  for (const auto& m : header)
    if (baseline(m)) {
      o << " " << m.method << " |";
      ++columns;
    }
  o << "\n|---|---|---|";
  for (int k = 0; k < columns; ++k) o << "---|";
  o << "\n";
  for (const BenchRow* t : settings) {
    o << "| " << knob_text(*t) << " | " << fmt("%.2f", t->horizon_mean_px) << " | " << fmt("%.1f", t->cpu_ms_median)
      << " |";
    for (const auto& m : match_horizon_error(rows, t->horizon_mean_px, &BenchRow::cpu_ms_median)) {
      if (!baseline(m)) continue;
      const std::string prefix = m.kind == MatchKind::AtMost ? "<= " : m.kind == MatchKind::NotReached ? "> " : "";
      o << " " << prefix << fmt("%.2f", t->cpu_ms_median > 0 ? m.frame_ms / t->cpu_ms_median : 0.0) << " |";
    }
    o << "\n";
  }
}

bool plot_error_vs_time(const std::string& png_path, const std::vector<BenchRow>& rows,
                        std::optional<double> target_px, const std::string& title) {
  const auto methods = by_method(rows);
  bool all_positive = true;
  for (const auto& r : rows) all_positive = all_positive && r.horizon_mean_px > 0.0;
  std::ostringstream gp;
  {
    gp << "set terminal pngcairo size 1000,650 noenhanced\n"
       << "set output '" << png_path << "'\n"
       << "set title '" << title << "'\n"
       << "set xlabel 'median frame time (ms, log)'\nset ylabel 'mean horizon error (px" << (all_positive ? ", log" : "")
       << ")'\n"
       << "set grid\nset key outside right top\nset logscale x\n"
       << (all_positive ? "set logscale y\n" : "set yrange [0:*]\n");
    for (size_t m = 0; m < methods.size(); ++m) {
      gp << "$m" << m << " << EOD\n";
      for (const BenchRow* r : methods[m].second)
        gp << num(r->frame_ms_median) << ' ' << num(r->horizon_mean_px) << " \""
           << (r->knob ? num(r->knob->value) : std::string("")) << "\"\n";
      gp << "EOD\n";
    }
    if (target_px && (*target_px > 0.0 || !all_positive))
      gp << "set arrow from graph 0, first " << num(*target_px) << " to graph 1, first " << num(*target_px)
         << " nohead dt 2 lc rgb 'gray40'\n";
    gp << "plot ";
    for (size_t m = 0; m < methods.size(); ++m)
      gp << (m ? ", " : "") << "$m" << m << " using 1:2 with linespoints lw 2 lc rgb '" << kColours[m % 8]
         << "' pt " << kPoints[m % 8] << " title '" << methods[m].first << "', $m" << m
         << " using 1:2:3 with labels offset char 0.8,0.6 font ',8' notitle";
    // The matched-error target across the whole width (an arrow), with a key entry (NaN plots nothing).
    if (target_px && (*target_px > 0.0 || !all_positive))
      gp << ", NaN with lines dt 2 lc rgb 'gray40' title 'matched error " << fmt("%.3f", *target_px) << " px'";
    gp << "\n";
  }
  return run_gnuplot(gp.str(), png_path, "ig bench", "error_vs_time.png");
}

bool plot_temporal_error(const std::string& png_path, const std::vector<BenchRow>& rows, const std::string& title) {
  std::ostringstream gp;
  gp << "set terminal pngcairo size 1000,650 noenhanced\n"
     << "set output '" << png_path << "'\n"
     << "set title '" << title << "'\n"
     << "set xlabel 'scenario time (s)'\nset ylabel 'temporal error (mean |dM - dR|, luma levels)'\n"
     << "set grid\nset key outside right top\nset yrange [0:*]\n";
  std::vector<const BenchRow*> curves;
  for (const auto& r : rows)
    if (r.default_knob && !r.temporal_error_by_time.empty()) curves.push_back(&r);
  for (size_t m = 0; m < curves.size(); ++m) {
    gp << "$m" << m << " << EOD\n";
    for (const auto& [t, v] : curves[m]->temporal_error_by_time) gp << num(t) << ' ' << num(v) << "\n";
    gp << "EOD\n";
  }
  if (curves.empty()) {
    // No pair (a single rendered frame): an empty plot that says so.
    gp << "set xrange [0:1]\nset label 'no temporal pairs' at graph 0.5, 0.5 center\nplot NaN notitle\n";
  } else {
    gp << "plot ";
    for (size_t m = 0; m < curves.size(); ++m)
      gp << (m ? ", " : "") << "$m" << m << " using 1:2 with linespoints lw 2 lc rgb '" << kColours[m % 8] << "' pt "
         << kPoints[m % 8] << " title '" << curves[m]->method << "'";
    gp << "\n";
  }
  return run_gnuplot(gp.str(), png_path, "ig bench", "temporal_error.png");
}

}  // namespace ig::session
