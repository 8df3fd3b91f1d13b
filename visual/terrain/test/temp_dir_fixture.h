#pragma once
// A test fixture with a temporary directory per test process: made before
// each test, removed with everything in it after.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>
#include <utility>

namespace ig::terrain::test {

class TempDirTest : public ::testing::Test {
 protected:
  // The directory: `prefix` followed by the process id, in the system's
  // temporary directory.
  explicit TempDirTest(const std::string& prefix)
      : dir_(std::filesystem::temp_directory_path() / (prefix + std::to_string(::getpid()))) {}
  void SetUp() override { std::filesystem::create_directories(dir_); }
  void TearDown() override {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }

  std::filesystem::path dir_;
};

}  // namespace ig::terrain::test
