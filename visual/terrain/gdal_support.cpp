#include "terrain/gdal_support.h"

#include <cpl_error.h>
#include <gdal_utils.h>

#include <cstdio>
#include <mutex>

namespace ig::terrain::gdal {

void register_once() {
  static std::once_flag once;
  std::call_once(once, [] { GDALAllRegister(); });
}

QuietErrors::QuietErrors() {
  CPLPushErrorHandler(CPLQuietErrorHandler);
  CPLErrorReset();
}

QuietErrors::~QuietErrors() { CPLPopErrorHandler(); }

std::string one_line(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r' || c == '\t') c = ' ';
  while (!s.empty() && (s.back() == ' ' || s.back() == '.')) s.pop_back();
  std::size_t start = 0;
  while (start < s.size() && s[start] == ' ') ++start;
  return s.substr(start);
}

std::string last_error(const char* otherwise) {
  const std::string m = one_line(CPLGetLastErrorMsg());
  return m.empty() ? std::string(otherwise) : m;
}

std::string number_arg(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

Dataset warp(GDALDatasetH src, const std::string& dest, const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  GDALWarpAppOptions* options = GDALWarpAppOptionsNew(argv.data(), nullptr);
  if (!options) return nullptr;
  int usage_error = 0;
  CPLErrorReset();
  Dataset out(GDALWarp(dest.c_str(), nullptr, 1, &src, options, &usage_error));
  GDALWarpAppOptionsFree(options);
  return out;
}

}  // namespace ig::terrain::gdal
