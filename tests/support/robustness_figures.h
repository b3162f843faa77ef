// Test helper: a robustness case's criterion and measured figure, recorded as the test's
// properties (gtest's RecordProperty), which --gtest_output=xml writes as attributes of its
// <testcase>. tools/robustness-report reads them into its table.
#pragma once

#include <gtest/gtest.h>

#include <string>

namespace candela::test {

inline void recordFigure(const std::string& criterion, const std::string& measured) {
  ::testing::Test::RecordProperty("criterion", criterion);
  ::testing::Test::RecordProperty("measured", measured);
}

}  // namespace candela::test
