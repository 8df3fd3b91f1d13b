// ig-send: `ig send` as a standalone binary for simulation-host scripts.
#include <string>
#include <vector>

#include "commands.h"

int main(int argc, char** argv) { return ig::app::run_send_command(std::vector<std::string>(argv + 1, argv + argc)); }
