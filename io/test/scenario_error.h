#pragma once
// The message of the ScenarioError a scenario text raises (a test failure,
// and "", when it parses).
#include <gtest/gtest.h>

#include <string>

#include "io/scenario.h"

inline std::string scenario_error_of(const std::string& text) {
  try {
    ig::io::parse_scenario(text);
  } catch (const ig::io::ScenarioError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected a ScenarioError for:\n" << text;
  return "";
}
