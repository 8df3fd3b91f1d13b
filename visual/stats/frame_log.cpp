#include "stats/frame_log.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace ig::stats {
namespace {
std::string format_number(double v) {
  if (!std::isfinite(v)) return "nan";  // never expected; kept visible rather than hidden
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4f", v);
  // Trim trailing zeros for compact CSV.
  std::string s(buf);
  s.erase(s.find_last_not_of('0') + 1);
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}
}  // namespace

Cell::Cell(std::string n, double v) : name(std::move(n)), text(format_number(v)), value(v) {}
Cell::Cell(std::string n, long long v) : name(std::move(n)), text(std::to_string(v)), value(double(v)) {}

Percentiles percentiles(std::vector<double> v) {
  Percentiles p;
  if (v.empty()) return p;
  std::sort(v.begin(), v.end());
  // Nearest-rank percentiles: reproducible, no interpolation surprises.
  auto rank = [&](double q) {
    const size_t k = size_t(std::ceil(q * double(v.size())));
    return v[std::clamp<size_t>(k, 1, v.size()) - 1];
  };
  p.median = v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
  p.p95 = rank(0.95);
  p.p99 = rank(0.99);
  p.max = v.back();
  double sum = 0;
  for (double x : v) sum += x;
  p.mean = sum / double(v.size());
  return p;
}

FrameLog::FrameLog(const std::string& csv_path) : path_(csv_path), out_(csv_path) {
  if (!out_) throw std::runtime_error(csv_path + ": cannot create frame log");
}

void FrameLog::add_row(const std::vector<Cell>& cells) {
  if (header_.empty()) {
    for (size_t k = 0; k < cells.size(); ++k) {
      for (size_t j = 0; j < k; ++j)  // a reader would see one of the two
        if (cells[j].name == cells[k].name) throw std::logic_error("frame log column " + cells[k].name + " twice");
      header_.push_back(cells[k].name);
      out_ << (k ? "," : "") << cells[k].name;
    }
    out_ << '\n';
  }
  if (cells.size() != header_.size()) throw std::logic_error("frame log row has a different column count");
  for (size_t k = 0; k < cells.size(); ++k) {
    if (cells[k].name != header_[k]) throw std::logic_error("frame log column " + cells[k].name + " out of order");
    out_ << (k ? "," : "") << cells[k].text;
    if (cells[k].name == "wall_ms" && cells[k].value) frame_ms_.push_back(*cells[k].value);
  }
  out_ << '\n';
  out_.flush();
}

nlohmann::json frame_time_summary(const std::vector<double>& frame_ms, double budget_ms) {
  const Percentiles p = percentiles(frame_ms);
  long long over = 0;
  for (double ms : frame_ms) over += ms > budget_ms;
  return {{"frames", frame_ms.size()},   {"median_ms", p.median}, {"p95_ms", p.p95},
          {"p99_ms", p.p99},             {"max_ms", p.max},       {"mean_ms", p.mean},
          {"budget_ms", budget_ms},      {"frames_over_budget", over}};
}

}  // namespace ig::stats
