// Perlin noise, FBm and turbulence (lrt draft §11.7; seed inventory §25: zero on the lattice,
// |noise| <= ~1, octave count falling with the footprint).
#include <gtest/gtest.h>

#include <random>

#include "textures/noise.h"

using namespace candela;

TEST(Noise, ZeroAtEveryIntegerLatticePoint) {
  for (int x = -300; x <= 300; x += 7)
    for (int y = -40; y <= 40; y += 3)
      for (int z = -5; z <= 5; ++z) ASSERT_EQ(noise(Float(x), Float(y), Float(z)), 0.f);
  // Far from the origin the cell index wraps without overflow.
  EXPECT_EQ(noise(1e9f, -3e9f, 65536.f), 0.f);
}

TEST(Noise, BoundedSmoothAndZeroMean) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<Float> u(-200, 200);
  double sum = 0, sumAbs = 0, maxAbs = 0;
  const int n = 400000;
  for (int i = 0; i < n; ++i) {
    Float v = noise(u(rng), u(rng), u(rng));
    sum += v;
    sumAbs += std::abs(v);
    maxAbs = std::max(maxAbs, double(std::abs(v)));
  }
  EXPECT_LE(maxAbs, 1.05);
  EXPECT_GT(maxAbs, 0.7);  // not degenerate
  EXPECT_NEAR(sum / n, 0, 0.005);
  // The constant turbulence substitutes for dropped octaves is the measured mean.
  EXPECT_NEAR(sumAbs / n, kMeanAbsNoise, 0.004);

  // Continuity: tiny steps change the value by tiny amounts (C2 fade, no jumps at cell faces).
  for (Float x = -3; x < 3; x += 0.0625f) {
    Float a = noise(x, 0.3f, 0.7f), b = noise(x + 1e-3f, 0.3f, 0.7f);
    EXPECT_LT(std::abs(a - b), 0.01f) << x;
  }
}

TEST(Noise, TwoArgumentFormIsTheHalfSlice) {
  EXPECT_EQ(noise(1.3f, 2.7f), noise(1.3f, 2.7f, 0.5f));
  EXPECT_NE(noise(1.3f, 2.7f), 0.f);
}

TEST(Noise, NonFiniteInputGivesZero) {
  const Float inf = std::numeric_limits<Float>::infinity(), nan = std::nanf("");
  EXPECT_EQ(noise(nan, 0.2f, 0.3f), 0.f);
  EXPECT_EQ(noise(0.1f, inf, 0.3f), 0.f);
  EXPECT_EQ(noise(0.1f, 0.2f, -inf), 0.f);
}

TEST(Noise, SmoothStep) {
  EXPECT_EQ(smoothStep(.3f, .7f, 0), 0.f);
  EXPECT_EQ(smoothStep(.3f, .7f, .3f), 0.f);
  EXPECT_FLOAT_EQ(smoothStep(.3f, .7f, .5f), .5f);
  EXPECT_EQ(smoothStep(.3f, .7f, .7f), 1.f);
  EXPECT_EQ(smoothStep(.3f, .7f, 2), 1.f);
}

TEST(Noise, OctaveCountFallsWithTheFootprint) {
  // n = 1 - log2(s^2)/2 = 1 - log2(s): a footprint of 2^-k allows k + 1 octaves.
  EXPECT_EQ(fbmOctaves(Vector3f(0, 0, 0), Vector3f(0, 0, 0), 8), 8.f);
  EXPECT_FLOAT_EQ(fbmOctaves(Vector3f(1.f / 8, 0, 0), Vector3f(0, 0, 0), 8), 4.f);
  EXPECT_FLOAT_EQ(fbmOctaves(Vector3f(0, 0, 0), Vector3f(0, 0.5f, 0), 8), 2.f);
  EXPECT_FLOAT_EQ(fbmOctaves(Vector3f(1, 0, 0), Vector3f(0, 0, 0), 8), 1.f);
  EXPECT_EQ(fbmOctaves(Vector3f(4, 0, 0), Vector3f(0, 0, 0), 8), 0.f);
  EXPECT_EQ(fbmOctaves(Vector3f(1e-6f, 0, 0), Vector3f(0, 0, 0), 8), 8.f);
  // The larger of the two footprints decides.
  EXPECT_FLOAT_EQ(fbmOctaves(Vector3f(1.f / 64, 0, 0), Vector3f(0, 0, 0.25f), 8), 3.f);
  Float previous = 9;
  for (Float s = 1e-4f; s < 100; s *= 1.5f) {
    Float n = fbmOctaves(Vector3f(s, 0, 0), Vector3f(0, s / 2, 0), 8);
    EXPECT_LE(n, previous);
    previous = n;
  }
  const Float inf = std::numeric_limits<Float>::infinity();
  EXPECT_EQ(fbmOctaves(Vector3f(inf, 0, 0), Vector3f(0, 0, 0), 8), 0.f);
  EXPECT_EQ(fbmOctaves(Vector3f(std::nanf(""), 0, 0), Vector3f(0, 0, 0), 8), 0.f);
}

TEST(Noise, FbmDropsDetailAsTheFootprintGrows) {
  Point3f p(0.37f, 1.21f, -2.9f);
  Vector3f zero;
  // One octave exactly at footprint 1 is plain noise; a footprint wider than 2 leaves nothing.
  EXPECT_FLOAT_EQ(fbm(p, Vector3f(1, 0, 0), zero, 0.5f, 8), noise(p));
  EXPECT_EQ(fbm(p, Vector3f(8, 0, 0), zero, 0.5f, 8), 0.f);
  // With a zero footprint all octaves are summed.
  Float expected = 0, lambda = 1, amplitude = 1;
  for (int i = 0; i < 5; ++i, lambda *= 1.99f, amplitude *= 0.5f)
    expected += amplitude * noise(p * lambda);
  EXPECT_NEAR(fbm(p, zero, zero, 0.5f, 5), expected, 1e-6f);
}

TEST(Noise, TurbulenceMeanDoesNotChangeWithTheFootprint) {
  // Clamped octaves contribute their mean, so far away (no octaves) the texture equals the
  // average it has close up.
  std::mt19937 rng(5);
  std::uniform_real_distribution<Float> u(-100, 100);
  const int n = 100000;
  double nearSum = 0;
  for (int i = 0; i < n; ++i)
    nearSum += turbulence(Point3f(u(rng), u(rng), u(rng)), Vector3f(), Vector3f(), 0.5f, 6);
  Float far = turbulence(Point3f(1.5f, 2.5f, 3.5f), Vector3f(100, 0, 0), Vector3f(), 0.5f, 6);
  Float expectedFar = kMeanAbsNoise * (1 - std::pow(0.5f, 6.f)) / 0.5f;
  EXPECT_FLOAT_EQ(far, expectedFar);
  EXPECT_NEAR(nearSum / n, far, 0.02 * far);
}

TEST(Noise, TurbulenceAsPbrtCountsThePartialOctavesMeanTwice) {
  // pbrt's clamped octaves (--turbulence pbrt): 0.2 for each octave from the first dropped one,
  // whose amplitude also carries the partial octave's faded-out 0.2.
  const Float omega = 0.5f;
  const int octaves = 6;
  // No octave kept (a footprint of 100): 0.2 (the partial one) + 0.2 (1 + omega + ... omega^5).
  Float far = turbulence(Point3f(1.5f, 2.5f, 3.5f), Vector3f(100, 0, 0), Vector3f(), omega, octaves,
                         ClampedOctaves::AsPbrt);
  EXPECT_FLOAT_EQ(far, 0.2f + 0.2f * (1 - std::pow(omega, Float(octaves))) / (1 - omega));
  // Every octave kept (no footprint): the mean form's sum, plus 0.2 omega^6 for the partial
  // octave that is not there.
  std::mt19937 rng(9);
  std::uniform_real_distribution<Float> u(-100, 100);
  for (int i = 0; i < 100; ++i) {
    Point3f p(u(rng), u(rng), u(rng));
    Float mean = turbulence(p, Vector3f(), Vector3f(), omega, octaves);
    Float pbrt = turbulence(p, Vector3f(), Vector3f(), omega, octaves, ClampedOctaves::AsPbrt);
    EXPECT_FLOAT_EQ(pbrt, mean + 0.2f * std::pow(omega, Float(octaves))) << i;
  }
  // A partial octave (a footprint of 2^-1.5: 2.5 octaves, half of the third faded in): the forms
  // differ, whatever the point, by pbrt's extra 0.2 omega^2 and by 0.2 - kMeanAbsNoise for what
  // is left of the partial octave's mean and for each dropped octave.
  const Vector3f dpdx(std::pow(2.f, -1.5f), 0, 0);
  const Float n = fbmOctaves(dpdx, Vector3f(), octaves);
  ASSERT_NEAR(n, 2.5f, 1e-5f);
  const Float w = smoothStep(.3f, .7f, n - 2);
  const Float delta = 0.2f - kMeanAbsNoise;
  Float expected = (0.2f + delta * (1 - w)) * std::pow(omega, 2.f);
  for (int k = 3; k < octaves; ++k) expected += delta * std::pow(omega, Float(k));
  for (int i = 0; i < 100; ++i) {
    Point3f p(u(rng), u(rng), u(rng));
    Float mean = turbulence(p, dpdx, Vector3f(), omega, octaves);
    Float pbrt = turbulence(p, dpdx, Vector3f(), omega, octaves, ClampedOctaves::AsPbrt);
    EXPECT_NEAR(pbrt - mean, expected, 1e-6f) << i;
  }
}
