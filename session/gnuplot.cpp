#include "session/gnuplot.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace ig::session {

bool run_gnuplot(const std::string& script, const std::string& png_path, const std::string& command,
                 const std::string& what) {
  const std::string script_path = png_path + ".gp";
  std::ofstream(script_path) << script;
  const std::string cmd = "gnuplot '" + script_path + "' 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) {
    std::cerr << command << ": cannot run gnuplot for " << png_path << "\n";
    return false;
  }
  char buf[256];
  std::string output;
  while (fgets(buf, sizeof buf, p)) output += buf;
  const int rc = pclose(p);
  if (rc != 0 || !std::filesystem::exists(png_path)) {
    std::cerr << command << ": " << what << " not written (is gnuplot installed? tools/setup.sh installs it): "
              << output << " (script kept: " << script_path << ")\n";
    return false;
  }
  std::filesystem::remove(script_path);
  return true;
}

}  // namespace ig::session
