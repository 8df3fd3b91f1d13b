#pragma once
// Options ig run, ig bench and ig send declare alike (cli_args.h has the
// checks every command shares): the scenario file, their one positional,
// and counts.

#include <string>

#include <CLI/CLI.hpp>

#include "cli_args.h"

namespace ig::app {

// The positional SCENARIO.json; `description` says what the command does with it.
inline CLI::Option* add_scenario_argument(CLI::App& app, std::string& file, const std::string& description) {
  return app.add_option("scenario", file, description)->option_text("SCENARIO.json");
}

// A count: a whole number from 1 (positive_int), its value shown as N in --help.
template <class T>
CLI::Option* add_count_option(CLI::App& app, const std::string& name, T& value, const std::string& description) {
  return app.add_option(name, value, description)->check(positive_int())->option_text("N");
}

}  // namespace ig::app
