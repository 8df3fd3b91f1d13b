#pragma once
// Small helpers shared by the subcommands' argument parsing: one place for
// value checks and their error messages.

#include <stdexcept>
#include <string>
#include <vector>

namespace ig::app {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class ArgReader {
 public:
  explicit ArgReader(const std::vector<std::string>& args) : args_(args) {}
  bool done() const { return k_ >= args_.size(); }
  const std::string& next() { return args_[k_++]; }
  // The value after `flag`; UsageError when missing.
  const std::string& value(const std::string& flag);
  int positive_int(const std::string& flag);
  double positive_double(const std::string& flag);
  double probability(const std::string& flag);  // [0, 1]
  // "WxH" into width/height.
  void size(const std::string& flag, int& width, int& height);

 private:
  const std::vector<std::string>& args_;
  size_t k_ = 0;
};

int parse_positive_int(const std::string& flag, const std::string& text);
double parse_double(const std::string& flag, const std::string& text);

}  // namespace ig::app
