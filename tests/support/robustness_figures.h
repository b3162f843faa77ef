// Test helper: a robustness case's criterion and measured figure, recorded as the test's
// properties (gtest's RecordProperty), which --gtest_output=xml writes with its <testcase>.
// tools/robustness-report reads them into its table.
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace candela::test {

inline void recordFigure(const std::string& criterion, const std::string& measured) {
  ::testing::Test::RecordProperty("criterion", criterion);
  ::testing::Test::RecordProperty("measured", measured);
}

// The measured figure formatted by printf's rules.
template <typename... Args>
void recordFigure(const std::string& criterion, const char* format, Args... args) {
  char measured[256];
  std::snprintf(measured, sizeof measured, format, args...);
  recordFigure(criterion, std::string(measured));
}

}  // namespace candela::test
