#pragma once
// The subcommands' command lines, parsed by CLI11: the checks every command
// shares (as CLI11 validators, so a bad value reads "--flag: reason") and one
// way to run the parse. Each command keeps its own synopsis (the usage
// lines); --help prints it followed by every option's description, taken
// from the options themselves (option_text: the value's name, e.g. "DIR";
// description: what it does and its default), so the two cannot disagree.

#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "session/scenario_runner.h"

namespace ig::app {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Thrown by parse_command_line on --help: the option list to print.
struct HelpRequested {
  std::string options;
};

// Every positional and option of `app` with its description, one block
// each, wrapped to `width` columns.
std::string describe_options(const CLI::App& app, int width = 100);

// --help or -h anywhere among the arguments.
inline bool help_requested(const std::vector<std::string>& argv) {
  for (const auto& a : argv)
    if (a == "--help" || a == "-h") return true;
  return false;
}

// A subcommand's argument parsing: the parsed arguments, or nullopt after
// printing to stdout on --help the usage text and the options' descriptions
// (the caller exits with 0: `return help_requested(argv) ? 0 : 2`), else to
// stderr "COMMAND: reason" and the usage text (the caller exits with 2).
template <class Parse>
auto parse_or_usage(const char* command, const char* usage, Parse parse, const std::vector<std::string>& argv)
    -> std::optional<decltype(parse(argv))> {
  try {
    return parse(argv);
  } catch (const HelpRequested& h) {
    std::cout << usage << "\n" << h.options;
    return std::nullopt;
  } catch (const UsageError& e) {
    std::cerr << command << ": " << e.what() << "\n" << usage << "(" << command << " --help describes every option)\n";
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
// declared; HelpRequested (describe_options(app)) when argv asks for --help.
void parse_command_line(CLI::App& app, const std::vector<std::string>& argv);

// Value checks shared by the commands, as CLI11 validators.
const CLI::Validator& positive_int();     // 1 .. 1e9
const CLI::Validator& positive_number();  // finite, > 0
const CLI::Validator& probability();      // [0, 1]
const CLI::Validator& can_node_id();      // 0 .. 255 (ig serve and ig send --can-node)
const CLI::Validator& can_altitude_id();  // CANaerospace 320, 322 or 332
// One of `choices`: "expected a, b or c, got 'x'".
CLI::Validator one_of(std::vector<std::string> choices);

// The view options ig run and ig serve share, into run's overrides: --size,
// --method, --headless and --window (the latter returned, for the caller's
// own window options to exclude or imply; parse_view_options reads it).
CLI::Option* add_view_options(CLI::App& app, session::RunOptions& run);

// --shader-dir DIR, the GLSL shaders' folder (ig run and ig bench).
CLI::Option* add_shader_dir_option(CLI::App& app, std::string& dir);

// "WxH" into width / height (each a positive integer).
CLI::Option* add_size_option(CLI::App& app, const std::string& name, std::optional<int>& width,
                             std::optional<int>& height);

int parse_positive_int(const std::string& flag, const std::string& text);
double parse_double(const std::string& flag, const std::string& text);

// ig serve's config when none is given: the installed scenarios/default.json
// (PREFIX/share/ig/scenarios), else the one beside the build's binary
// (bin/scenarios), else scenarios/default.json in the working directory.
std::string default_scenario_file();

// The positional SCENARIO.json of ig run, bench and send; `description`
// says what the command does with it.
inline CLI::Option* add_scenario_argument(CLI::App& app, std::string& file, const std::string& description) {
  return app.add_option("scenario", file, description)->option_text("SCENARIO.json");
}

// A count: a whole number from 1 (positive_int), its value shown as N in --help.
template <class T>
CLI::Option* add_count_option(CLI::App& app, const std::string& name, T& value, const std::string& description) {
  return app.add_option(name, value, description)->check(positive_int())->option_text("N");
}

}  // namespace ig::app
