#pragma once
// Small helpers shared by the subcommands' argument parsing: one place for
// value checks and their error messages.

#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace ig::app {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// --help or -h anywhere among the arguments.
inline bool help_requested(const std::vector<std::string>& argv) {
  for (const auto& a : argv)
    if (a == "--help" || a == "-h") return true;
  return false;
}

// A subcommand's argument parsing: the parsed arguments, or nullopt after
// printing the usage text, to stdout on --help (the caller exits with 0:
// `return help_requested(argv) ? 0 : 2`), else to stderr after
// "COMMAND: reason" (the caller exits with 2).
template <class Parse>
auto parse_or_usage(const char* command, const char* usage, Parse parse, const std::vector<std::string>& argv)
    -> std::optional<decltype(parse(argv))> {
  if (help_requested(argv)) {
    std::cout << usage;
    return std::nullopt;
  }
  try {
    return parse(argv);
  } catch (const UsageError& e) {
    std::cerr << command << ": " << e.what() << "\n" << usage;
    return std::nullopt;
  }
}

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
  // CAN options shared by ig serve and ig send: a node id 0..255, and the
  // CANaerospace altitude id 320, 322 or 332.
  int can_node(const std::string& flag);
  int can_altitude_id(const std::string& flag);
  // "WxH" into width/height.
  void size(const std::string& flag, int& width, int& height);

 private:
  const std::vector<std::string>& args_;
  size_t k_ = 0;
};

int parse_positive_int(const std::string& flag, const std::string& text);
// ig serve's config when none is given: the installed scenarios/default.json
// (PREFIX/share/ig/scenarios), else the one beside the build's binary, else
// the source tree's.
std::string default_scenario_file();
double parse_double(const std::string& flag, const std::string& text);

}  // namespace ig::app
