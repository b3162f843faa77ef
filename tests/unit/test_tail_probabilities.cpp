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

TEST(TailProbabilities, StudentT) {
  // One and two degrees of freedom have closed forms: 1 - 2 atan(t) / pi (Cauchy) and
  // 1 - t / sqrt(2 + t^2).
  for (double t : {0.1, 1.0, 3.0, 40.0}) {
    EXPECT_NEAR(studentTwoSidedTail(t, 1), 1 - 2 * std::atan(t) / 3.14159265358979323846, 1e-12)
        << t;
    EXPECT_NEAR(studentTwoSidedTail(t, 2), 1 - t / std::sqrt(2 + t * t), 1e-12) << t;
  }
  // Two-sided 5% and 1% critical values (standard tables, 3 decimals).
  EXPECT_NEAR(studentTwoSidedTail(2.228, 10), 0.05, 1e-4);
  EXPECT_NEAR(studentTwoSidedTail(2.807, 23), 0.01, 1e-4);
  EXPECT_NEAR(studentTwoSidedTail(-2.704, 40), 0.01, 1e-4);
  // Many degrees of freedom: the normal's tail, also far out (at 1e8 dof the relative
  // difference at t = 5 is (t^4 + 2 t^2) / (4 dof), about 2e-6).
  for (double t : {1.0, 3.0, 5.0})
    EXPECT_NEAR(studentTwoSidedTail(t, 1e8) / normalTwoSidedTail(t), 1, 1e-5) << t;
  EXPECT_EQ(studentTwoSidedTail(0, 5), 1);
}

}  // namespace
}  // namespace candela::stats
