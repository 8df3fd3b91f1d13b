#pragma once
// What a run leaves behind, shared by ig run and ig serve: frames.csv (one
// row per frame and channel), captured PNGs, final.png, summary.json and the
// frametime.png plot, plus the progress line on a terminal and the warnings
// about frames that show no terrain or look from under it (TerrainWatch).

#include <chrono>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "session/scenario_runner.h"
#include "session/terrain_watch.h"
#include "stats/frame_log.h"

namespace ig::session {

class RunOutputs {
 public:
  RunOutputs(const std::filesystem::path& dir, std::string command, bool progress);

  // After runner.render_frame / render_pose: reads back and writes PNGs when
  // asked, presents the first channel in a window, logs one row per channel
  // (`extra` appends columns, e.g. pose intake state).
  void frame(ScenarioRunner& runner, const FrameResult& f, bool capture, bool last, int total_frames,
             const std::function<void(std::vector<stats::Cell>&)>& extra = nullptr);

  // Writes summary.json (the common fields plus `extra`) and frametime.png,
  // prints the closing lines. Returns the process exit code.
  int finish(ScenarioRunner& runner, const std::string& scenario_file, nlohmann::json extra = {});

  // Prints a warning line on stderr (after the progress line, if any).
  void warn(const std::string& line) const;
  const TerrainWatch& terrain_watch() const { return watch_; }

 private:
  std::filesystem::path dir_;
  std::string command_;
  bool progress_;
  stats::FrameLog log_;
  std::vector<std::string> captured_;
  int rendered_ = 0;
  bool final_written_ = false;
  std::chrono::steady_clock::time_point start_;
  TerrainWatch watch_;
  // Paged heights: frames that waited on a tile, tiles loaded.
  long long frames_waited_on_io_ = 0, page_waits_ = 0, page_ins_ = 0;
  // Paged imagery: frames whose window move was held, held moves, tiles
  // they missed, tiles loaded, frames that waited on an imagery tile.
  long long imagery_frames_held_ = 0, imagery_held_ = 0, imagery_missing_ = 0, imagery_page_ins_ = 0,
            imagery_frames_waited_ = 0;
  // Timed passes (RunOptions::pass_times): every channel's frames, per pass in the order first drawn.
  std::vector<std::pair<std::string, std::vector<double>>> pass_ms_;
  void add_pass_times(const render::ViewResult& view);
};

}  // namespace ig::session
