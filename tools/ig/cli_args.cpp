#include "cli_args.h"

#include <cmath>
#include <cstdlib>

#include "gl/shader_program.h"

namespace ig::app {

int parse_positive_int(const std::string& flag, const std::string& v) {
  size_t used = 0;
  long n = 0;
  try {
    n = std::stol(v, &used);
  } catch (...) {
    used = 0;
  }
  if (used != v.size() || n <= 0 || n > 1000000000L)
    throw UsageError(flag + ": expected a positive integer, got '" + v + "'");
  return int(n);
}

double parse_double(const std::string& flag, const std::string& v) {
  size_t used = 0;
  double d = 0;
  try {
    d = std::stod(v, &used);
  } catch (...) {
    used = 0;
  }
  if (used != v.size() || !std::isfinite(d)) throw UsageError(flag + ": expected a number, got '" + v + "'");
  return d;
}

const std::string& ArgReader::value(const std::string& flag) {
  if (done()) throw UsageError(flag + ": missing value");
  return next();
}

int ArgReader::positive_int(const std::string& flag) { return parse_positive_int(flag, value(flag)); }

int ArgReader::can_node(const std::string& flag) {
  const std::string& v = value(flag);
  char* end = nullptr;
  const long n = std::strtol(v.c_str(), &end, 10);
  if (v.empty() || *end || n < 0 || n > 255) throw UsageError(flag + ": expected 0..255, got '" + v + "'");
  return int(n);
}

int ArgReader::can_altitude_id(const std::string& flag) {
  const int id = positive_int(flag);
  if (id != 320 && id != 322 && id != 332)
    throw UsageError(flag + ": expected 320, 322 or 332, got " + std::to_string(id));
  return id;
}

double ArgReader::positive_double(const std::string& flag) {
  const double d = parse_double(flag, value(flag));
  if (!(d > 0)) throw UsageError(flag + ": must be > 0");
  return d;
}

double ArgReader::probability(const std::string& flag) {
  const double d = parse_double(flag, value(flag));
  if (!(d >= 0 && d <= 1)) throw UsageError(flag + ": must be in [0, 1]");
  return d;
}

void ArgReader::size(const std::string& flag, int& width, int& height) {
  const std::string v = value(flag);
  const auto x = v.find('x');
  if (x == std::string::npos) throw UsageError(flag + ": expected WxH, got '" + v + "'");
  width = parse_positive_int(flag, v.substr(0, x));
  height = parse_positive_int(flag, v.substr(x + 1));
}

std::string default_scenario_file() {
  if (auto dir = gl::installed_data_dir("scenarios", "default.json"); !dir.empty()) return dir + "/default.json";
  return std::string(IG_SOURCE_DIR) + "/scenarios/default.json";
}

}  // namespace ig::app
