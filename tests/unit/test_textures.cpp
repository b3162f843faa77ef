// The texture classes of lrt draft ch. 11, built directly (the factory has its own tests).
#include <gtest/gtest.h>

#include <random>

#include "textures/basic_textures.h"
#include "textures/checkerboard.h"
#include "textures/dots.h"
#include "textures/image_texture.h"
#include "textures/solid_textures.h"

using namespace candela;

namespace {

SurfaceInteraction atUV(Float u, Float v, Float dudx = 0, Float dvdy = 0) {
  SurfaceInteraction si;
  si.uv = Point2f(u, v);
  si.p = Point3f(u, v, 0);
  si.dudx = dudx;
  si.dvdy = dvdy;
  si.dpdx = Vector3f(dudx, 0, 0);
  si.dpdy = Vector3f(0, dvdy, 0);
  return si;
}

const ConstantTexture<Float> kOne(1), kZero(0);

Checkerboard2DTexture<Float> checker(CheckerboardAA aa) {
  return Checkerboard2DTexture<Float>(std::make_unique<UVMapping2D>(), &kZero, &kOne, aa);
}

}  // namespace

TEST(Checkerboard, ClosedFormFraction) {
  // Inside one check: exactly that check.
  EXPECT_EQ(checkerboardTex2Fraction(0.5f, 0.5f, 0.1f, 0.1f), 0.f);
  EXPECT_EQ(checkerboardTex2Fraction(1.5f, 0.5f, 0.1f, 0.1f), 1.f);
  EXPECT_EQ(checkerboardTex2Fraction(-0.5f, 0.5f, 0.1f, 0.1f), 1.f);
  EXPECT_EQ(checkerboardTex2Fraction(-0.5f, -0.5f, 0.4f, 0.4f), 0.f);
  // Straddling the s = 1 edge evenly, inside one t cell: half and half.
  EXPECT_FLOAT_EQ(checkerboardTex2Fraction(1, 0.5f, 0.5f, 0.25f), 0.5f);
  // A quarter of the box in the odd column: [0.75, 1.25] x cell 0 -> 0.5; [0.5, 1.25] -> 1/3.
  EXPECT_FLOAT_EQ(checkerboardTex2Fraction(0.875f, 0.5f, 0.375f, 0.1f), 1.f / 3);
  // Corner of four checks: two of each.
  EXPECT_FLOAT_EQ(checkerboardTex2Fraction(1, 1, 0.5f, 0.5f), 0.5f);
  // A footprint flat in one direction is the point value there (the draft's 0/0).
  EXPECT_FLOAT_EQ(checkerboardTex2Fraction(1, 0.5f, 0.5f, 0), 0.5f);
  EXPECT_FLOAT_EQ(checkerboardTex2Fraction(0.5f, 1, 0, 0.25f), 0.5f);
  // Wider than two checks: the mean.
  EXPECT_EQ(checkerboardTex2Fraction(0.3f, 7.1f, 1.5f, 0.2f), 0.5f);
  EXPECT_EQ(checkerboardTex2Fraction(0.3f, 7.1f, 0.2f, 1e30f), 0.5f);
  EXPECT_EQ(checkerboardTex2Fraction(std::nanf(""), 0, 0, 0), 0.5f);
}

TEST(Checkerboard, ClosedFormMatchesNumericBoxAverage) {
  std::mt19937 rng(2);
  std::uniform_real_distribution<Float> u(-5, 5), d(0.01f, 0.99f);
  for (int i = 0; i < 100; ++i) {
    Float s = u(rng), t = u(rng), ds = d(rng), dt = d(rng);
    const int n = 400;
    double sum = 0;
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
        sum += checkIsTex2(s - ds + 2 * ds * (j + 0.5f) / n, t - dt + 2 * dt * (k + 0.5f) / n);
    EXPECT_NEAR(checkerboardTex2Fraction(s, t, ds, dt), sum / (n * n), 0.006) << s << " " << t;
  }
}

TEST(Checkerboard, AntialiasedToHalfFarAwayAndExactUpClose) {
  auto closed = checker(CheckerboardAA::ClosedForm);
  auto none = checker(CheckerboardAA::None);
  std::mt19937 rng(8);
  std::uniform_real_distribution<Float> u(-50, 50);
  for (int i = 0; i < 500; ++i) {
    Float s = u(rng), t = u(rng);
    Float parity = checkIsTex2(s, t) ? 1 : 0;
    // Many checks per pixel: exactly the mean.
    EXPECT_EQ(closed.evaluate(atUV(s, t, 3, 2.5f)), 0.5f);
    // A tiny footprint away from the edges: exactly the check's value, as point sampling.
    Float fs = s - std::floor(s), ft = t - std::floor(t);
    if (std::min({fs, 1 - fs, ft, 1 - ft}) > 1e-3f) {
      EXPECT_EQ(closed.evaluate(atUV(s, t, 1e-4f, 1e-4f)), parity);
      EXPECT_EQ(none.evaluate(atUV(s, t, 3, 3)), parity);
    }
  }
}

TEST(Checkerboard, SupersamplingAveragesOverTheFootprint) {
  auto super = checker(CheckerboardAA::Supersample);
  // No footprint: every sample at the same point.
  EXPECT_EQ(super.evaluate(atUV(0.5f, 0.5f)), 0.f);
  EXPECT_FLOAT_EQ(super.evaluate(atUV(1.5f, 0.5f)), 1.f);
  // A footprint of 8 checks: the jittered samples fall on both colours about evenly at each
  // point (an unjittered 4x4 grid would put all 16 on one colour and alias).
  std::mt19937 rng(4);
  std::uniform_real_distribution<Float> u(-20, 20);
  double sum = 0, sumSq = 0;
  const int n = 2000;
  for (int i = 0; i < n; ++i) {
    Float v = super.evaluate(atUV(u(rng), u(rng), 8, 8));
    EXPECT_EQ(super.evaluate(atUV(3.3f, 1.7f, 8, 8)), super.evaluate(atUV(3.3f, 1.7f, 8, 8)));
    sum += v;
    sumSq += v * v;
  }
  EXPECT_NEAR(sum / n, 0.5, 0.02);
  // Per-point values spread around the mean far less than 0/1 answers would (variance 1/4).
  EXPECT_LT(sumSq / n - (sum / n) * (sum / n), 0.05);
}

TEST(Checkerboard, SolidParity) {
  Checkerboard3DTexture<Float> point(TextureMapping3D(Transform()), &kZero, &kOne, false);
  EXPECT_EQ(point.evaluate(atUV(0.5f, 0.5f)), 0.f);
  EXPECT_EQ(point.evaluate(atUV(1.5f, 0.5f)), 1.f);
  EXPECT_EQ(point.evaluate(atUV(-0.5f, -0.5f)), 0.f);
  SurfaceInteraction si = atUV(0.5f, 0.5f);
  si.p.z = 2.5f;
  EXPECT_EQ(point.evaluate(si), 0.f);
  si.p.z = -0.5f;
  EXPECT_EQ(point.evaluate(si), 1.f);
  Checkerboard3DTexture<Float> super(TextureMapping3D(Transform()), &kZero, &kOne, true);
  EXPECT_EQ(super.evaluate(atUV(1.5f, 0.5f)), 1.f);
  Float mixed = super.evaluate(atUV(1, 0.5f, 1, 0));
  EXPECT_GT(mixed, 0.2f);
  EXPECT_LT(mixed, 0.8f);
}

TEST(Textures, ScaleMixBilerpUV) {
  ConstantTexture<Spectrum> a(Spectrum(1, 2, 3)), b(Spectrum(0.5f));
  ConstantTexture<Float> quarter(0.25f);
  SurfaceInteraction si = atUV(0.25f, 0.75f);
  EXPECT_EQ(ScaleTexture<Spectrum>(&a, &b).evaluate(si), Spectrum(0.5f, 1, 1.5f));
  EXPECT_EQ(MixTexture<Spectrum>(&a, &b, &quarter).evaluate(si),
            Spectrum(1, 2, 3) * 0.75f + Spectrum(0.5f) * 0.25f);
  BilerpTexture<Float> bilerp(std::make_unique<UVMapping2D>(), 1, 2, 3, 4);
  EXPECT_EQ(bilerp.evaluate(atUV(0, 0)), 1.f);
  EXPECT_EQ(bilerp.evaluate(atUV(0, 1)), 2.f);
  EXPECT_EQ(bilerp.evaluate(atUV(1, 0)), 3.f);
  EXPECT_EQ(bilerp.evaluate(atUV(1, 1)), 4.f);
  EXPECT_FLOAT_EQ(bilerp.evaluate(si),
                  0.75f * 0.25f * 1 + 0.75f * 0.75f * 2 + 0.25f * 0.25f * 3 + 0.25f * 0.75f * 4);
  UVTexture uv(std::make_unique<UVMapping2D>());
  EXPECT_EQ(uv.evaluate(atUV(2.25f, -0.25f)), Spectrum(0.25f, 0.75f, 0));
}

TEST(Textures, PolkaDots) {
  DotsTexture<Float> dots(std::make_unique<UVMapping2D>(), &kZero, &kOne);
  int inside = 0;
  const int n = 200;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      Float s = -20 + 40.f * (i + 0.5f) / n, t = -20 + 40.f * (j + 0.5f) / n;
      bool in = dots.evaluate(atUV(s, t)) == 1;
      inside += in;
      if (in) {
        // Within radius .35 of a centre at most .15 from the cell's centre.
        Float ds = s - std::floor(s + 0.5f), dt = t - std::floor(t + 0.5f);
        EXPECT_LT(ds * ds + dt * dt, 0.5f * 0.5f);
      }
    }
  // About half the cells hold a dot covering pi .35^2 of the cell.
  Float fraction = Float(inside) / (n * n);
  EXPECT_GT(fraction, 0.5f * kPi * 0.35f * 0.35f * 0.6f);
  EXPECT_LT(fraction, 0.5f * kPi * 0.35f * 0.35f * 1.4f);
}

TEST(Textures, SolidNoiseTexturesAreFiniteAndBounded) {
  MarbleTexture marble(TextureMapping3D(Transform()), 8, 0.5f, 1, 0.2f);
  FBmTexture<Float> fbm(TextureMapping3D(Transform()), 8, 0.5f);
  WrinkledTexture<Spectrum> wrinkled(TextureMapping3D(Transform()), 8, 0.5f);
  WindyTexture<Float> windy{TextureMapping3D(Transform())};
  std::mt19937 rng(6);
  std::uniform_real_distribution<Float> u(-30, 30);
  for (int i = 0; i < 2000; ++i) {
    SurfaceInteraction si = atUV(u(rng), u(rng), 0.01f, 0.01f);
    si.p.z = u(rng);
    Spectrum m = marble.evaluate(si);
    for (int c = 0; c < 3; ++c) {
      EXPECT_GE(m[c], 0.2f * 1.5f - 1e-5f);
      EXPECT_LE(m[c], 0.6f * 1.5f + 1e-5f);
    }
    EXPECT_LE(std::abs(fbm.evaluate(si)), 2.1f);
    Spectrum w = wrinkled.evaluate(si);
    EXPECT_GE(w[0], 0.f);
    EXPECT_EQ(w[0], w[1]);
    EXPECT_TRUE(std::isfinite(windy.evaluate(si)));
  }
}

TEST(Textures, ImageTextureScaleAndGamma) {
  ImageBuffer img(2, 1, {"R", "G", "B"});
  img.at(0, 0, 0) = 0.5f, img.at(0, 0, 1) = 0.25f, img.at(0, 0, 2) = 1;
  img.at(1, 0, 0) = img.at(1, 0, 1) = img.at(1, 0, 2) = -0.5f;
  std::vector<Spectrum> s = spectrumTexels(img, 2, 2);
  EXPECT_EQ(s[0], Spectrum(1, 0.25f, 4));
  EXPECT_EQ(s[1], Spectrum(0));  // negative before a gamma: 0
  std::vector<Float> f = floatTexels(img, 1, 1);
  EXPECT_FLOAT_EQ(f[0], Spectrum(0.5f, 0.25f, 1).y());
  EXPECT_FLOAT_EQ(f[1], -0.5f);
  ImageBuffer grey(1, 1, {"Y"});
  grey.at(0, 0, 0) = 0.7f;
  EXPECT_EQ(spectrumTexels(grey, 1, 1)[0], Spectrum(0.7f));
  EXPECT_EQ(floatTexels(grey, 1, 1)[0], 0.7f);

  auto mip = std::make_shared<const MIPMap<Spectrum>>(2, 1, s, WrapMode::Clamp);
  ImageTexture<Spectrum> tex(std::make_unique<UVMapping2D>(), mip, false, 8);
  EXPECT_EQ(tex.evaluate(atUV(0.25f, 0.5f)), Spectrum(1, 0.25f, 4));
  ImageTexture<Spectrum> tri(std::make_unique<UVMapping2D>(), mip, true, 8);
  EXPECT_EQ(tri.evaluate(atUV(0.75f, 0.5f)), Spectrum(0));
}
