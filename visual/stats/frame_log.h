#pragma once
// Per-frame log (frames.csv, one row per frame and channel) and the run
// summary (summary.json). Columns are fixed by the first row, each name once;
// every later row must carry the same names in the same order.

#include <fstream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace ig::stats {

// A value is a number or a short text (e.g. the passes that ran).
struct Cell {
  std::string name;
  std::string text;                   // as written to the CSV
  std::optional<double> value;        // numeric cells: the number itself (statistics use it, not the text)
  Cell(std::string n, double v);
  Cell(std::string n, long long v);
  Cell(std::string n, int v) : Cell(std::move(n), static_cast<long long>(v)) {}
  Cell(std::string n, std::string v) : name(std::move(n)), text(std::move(v)) {}
};

struct Percentiles {
  double median = 0, p95 = 0, p99 = 0, max = 0, mean = 0;
};
Percentiles percentiles(std::vector<double> values);

class FrameLog {
 public:
  // Throws std::runtime_error naming the file when it cannot be created.
  explicit FrameLog(const std::string& csv_path);
  void add_row(const std::vector<Cell>& cells);
  // Frame time of each logged frame (the "wall_ms" column), for the summary.
  const std::vector<double>& frame_ms() const { return frame_ms_; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::ofstream out_;
  std::vector<std::string> header_;
  std::vector<double> frame_ms_;
};

// Frame-time statistics for summary.json: median/p95/p99/max and frames over budget.
nlohmann::json frame_time_summary(const std::vector<double>& frame_ms, double budget_ms);

}  // namespace ig::stats
