// The statistical tests' tail probabilities against tabulated values: a wrong p-value would make
// every chi-square test in the suite pass or fail for the wrong reason.
#include <gtest/gtest.h>

#include "support/tail_probabilities.h"

namespace candela::stats {
namespace {

TEST(TailProbabilities, ChiSquareCriticalValues) {
  // 5% and 0.1% critical values of the chi-square distribution (standard tables, 4 digits).
  EXPECT_NEAR(chiSquareSurvival(3.841, 1), 0.05, 2e-5);
  EXPECT_NEAR(chiSquareSurvival(18.307, 10), 0.05, 2e-5);
  EXPECT_NEAR(chiSquareSurvival(124.342, 100), 0.05, 2e-5);
  EXPECT_NEAR(chiSquareSurvival(29.588, 10), 0.001, 1e-6);
  // Two degrees of freedom: exactly exp(-x/2), both far in the tail and near the middle.
  for (double x : {0.5, 2.0, 10.0, 60.0})
    EXPECT_NEAR(chiSquareSurvival(x, 2) / std::exp(-x / 2), 1, 1e-12) << x;
  EXPECT_EQ(chiSquareSurvival(0, 5), 1);
}

TEST(TailProbabilities, PoissonAndSidak) {
  // P(X >= 1) = 1 - e^-λ; P(X >= 2) = 1 - e^-λ (1 + λ).
  for (double lambda : {0.1, 1.0, 7.5}) {
    EXPECT_NEAR(poissonUpperTail(1, lambda), 1 - std::exp(-lambda), 1e-12);
    EXPECT_NEAR(poissonUpperTail(2, lambda), 1 - std::exp(-lambda) * (1 + lambda), 1e-12);
  }
  EXPECT_EQ(poissonUpperTail(0, 3), 1);
  EXPECT_NEAR(1 - std::pow(1 - sidak(0.01, 20), 20), 0.01, 1e-12);
}

}  // namespace
}  // namespace candela::stats
