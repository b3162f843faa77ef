// The Metropolis chain state (Kelemen et al. 2002; pbrt 3e §16.4.3): a rejected proposal restores
// every number it touched, a large step makes fresh numbers, the streams are independent of
// each other's length, and lazily applied small steps have the variance of the steps they stand
// for (k missed steps of sigma: variance k sigma²), checked by a chi-square test on the sample
// variance at significance 0.001. Fixed seeds.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "integrators/metropolis/primary_samples.h"
#include "support/tail_probabilities.h"

namespace candela {
namespace {

std::vector<Float> read(PrimarySamples& s, int stream, int n) {
  std::vector<Float> v;
  for (int i = 0; i < n; ++i) v.push_back(s.get(stream, i));
  return v;
}

TEST(PrimarySamples, RejectRestoresWhatTheProposalTouched) {
  PrimarySamples s(1, 2, 0.05f, 0.3f);
  s.startLargeStep();
  std::vector<Float> current = read(s, 0, 8);
  s.accept();
  for (int iteration = 0; iteration < 50; ++iteration) {
    s.startIteration();
    std::vector<Float> proposed = read(s, 0, 8);
    EXPECT_NE(proposed, current);  // every step moves the numbers it reads
    if (iteration % 3 == 0) {
      s.accept();
      current = proposed;
    } else {
      s.reject();
    }
  }
  // Reading without a new iteration gives the current state's numbers back.
  EXPECT_EQ(read(s, 0, 8), current);
}

TEST(PrimarySamples, StreamsDoNotShiftEachOther) {
  // A path that reads more of one stream after a small step still finds its other streams'
  // numbers where they were: each (stream, index) is its own variable.
  PrimarySamples s(5, 6, 0.001f, 0);
  s.startLargeStep();
  std::vector<Float> camera = read(s, 0, 4);
  read(s, 1, 2);
  s.accept();
  s.startIteration();
  read(s, 1, 10);  // the light subpath got longer
  std::vector<Float> moved = read(s, 0, 4);
  for (int i = 0; i < 4; ++i) {
    Float d = std::abs(moved[size_t(i)] - camera[size_t(i)]);
    EXPECT_LT(std::min(d, 1 - d), 0.01f) << i;  // within 10 sigma on the circle
  }
}

TEST(PrimarySamples, LazySmallStepsHaveTheVarianceOfTheStepsTheyReplace) {
  const Float sigma = 0.002f;
  const int missed = 25;  // accepted small steps that did not read the number
  const int trials = 2000;
  double sumSq = 0;
  int used = 0;
  for (int t = 0; t < trials; ++t) {
    PrimarySamples s(uint64_t(t), 9, sigma, 0);
    s.startLargeStep();
    Float start = s.get(0, 0);
    s.accept();
    for (int k = 0; k < missed - 1; ++k) {
      s.startIteration();
      s.get(1, 0);  // another number moves; this one is left behind
      s.accept();
    }
    s.startIteration();
    Float end = s.get(0, 0);
    // Displacement on the circle [0, 1): far from the wrap-around at these step sizes.
    double d = end - start;
    d -= std::round(d);
    sumSq += d * d;
    ++used;
  }
  // (n) s² / σ² is chi-square with n degrees of freedom (the mean is known to be 0).
  double variance = double(missed) * sigma * sigma;
  double x = sumSq / variance;
  double p = stats::chiSquareSurvival(x, used);
  EXPECT_GT(p, 0.0005) << "variance ratio " << sumSq / used / variance;
  EXPECT_LT(p, 0.9995) << "variance ratio " << sumSq / used / variance;
}

TEST(PrimarySamples, AcceptedLargeStepRenewsNumbersReadLater) {
  PrimarySamples s(3, 4, 0.001f, 1);  // every proposal a large step
  s.startLargeStep();
  Float first = s.get(0, 3);
  s.accept();
  s.startIteration();
  s.get(0, 0);
  s.accept();  // the large step is accepted without reading index 3
  s.startIteration();
  Float later = s.get(0, 3);
  // A small step of 0.001 could not have moved it this far; a fresh uniform almost surely does.
  EXPECT_GT(std::abs(later - first), 0.01f);
}

}  // namespace
}  // namespace candela
