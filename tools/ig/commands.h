#pragma once
// Subcommands of the `ig` executable. Each takes the arguments after its own
// name and returns the process exit code; errors go to stderr as one line.

#include <string>
#include <vector>

namespace ig::app {

int run_info_command(const std::vector<std::string>& args);  // ig info FILE [...]
int run_run_command(const std::vector<std::string>& args);   // ig run SCENARIO [...]
int run_serve_command(const std::vector<std::string>& args); // ig serve [...]
int run_send_command(const std::vector<std::string>& args);  // ig send SCENARIO --to ADDR:PORT [...]
int run_bench_command(const std::vector<std::string>& args); // ig bench SCENARIO --methods LIST [...]

}  // namespace ig::app
