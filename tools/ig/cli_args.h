#pragma once
// The subcommands' command lines, parsed by CLI11: the checks every command
// shares (as CLI11 validators, so a bad value reads "--flag: reason") and one
// way to run the parse. Each command keeps its own usage text (--help).

#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

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

// A subcommand from its command line to its exit status: 0 after --help, 2
// after a usage error (parse_or_usage), else what run(args) returns; 1 after
// "COMMAND: what" for anything it throws.
template <class Parse, class Run>
int run_command(const char* command, const char* usage, Parse parse, const std::vector<std::string>& argv, Run run) {
  const auto parsed = parse_or_usage(command, usage, parse, argv);
  if (!parsed) return help_requested(argv) ? 0 : 2;
  try {
    return run(*parsed);
  } catch (const std::exception& e) {
    std::cerr << command << ": " << e.what() << "\n";
    return 1;
  }
}

// Parses argv with the options and positionals `app` declares. Given twice,
// an option's last value counts. Throws UsageError on any mistake: CLI11's
// message, or "unknown option X" / "unexpected argument X" for what nothing
// declared. No generated --help: the caller prints its usage text.
void parse_command_line(CLI::App& app, const std::vector<std::string>& argv);

// Value checks shared by the commands, as CLI11 validators.
const CLI::Validator& positive_int();     // 1 .. 1e9
const CLI::Validator& positive_number();  // finite, > 0
const CLI::Validator& probability();      // [0, 1]
const CLI::Validator& can_node_id();      // 0 .. 255 (ig serve and ig send --can-node)
const CLI::Validator& can_altitude_id();  // CANaerospace 320, 322 or 332
// One of `choices`: "expected a, b or c, got 'x'".
CLI::Validator one_of(std::vector<std::string> choices);

// "WxH" into width / height (each a positive integer).
CLI::Option* add_size_option(CLI::App& app, const std::string& name, std::optional<int>& width,
                             std::optional<int>& height);

int parse_positive_int(const std::string& flag, const std::string& text);
double parse_double(const std::string& flag, const std::string& text);

// ig serve's config when none is given: the installed scenarios/default.json
// (PREFIX/share/ig/scenarios), else the one beside the build's binary, else
// the source tree's.
std::string default_scenario_file();

}  // namespace ig::app
