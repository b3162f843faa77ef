// How a BSDF picks among its components (reflection/bsdf.h): a smooth dielectric's reflection and
// refraction by the Fresnel term, so that each pick weighs f |cos| / pdf = its tint (times the
// radiance scaling for a refraction) instead of 2F and 2(1 - F) for half-and-half picks; a rough
// dielectric by the Fresnel term of the microfacet it drew, each sample weighing at most its tint.
// Fresnel reflectances here come from the amplitude coefficients (Hecht, Optics §4.6), not from
// the renderer's fresnelDielectric.
#include <gtest/gtest.h>

#include <cmath>

#include "core/memory.h"
#include "materials/glass.h"
#include "reflection/bsdf.h"
#include "reflection/specular.h"
#include "reflection/trowbridge_reitz_dielectric.h"

namespace candela {
namespace {

// Unpolarised reflectance from the side of index n1 at incidence cosine cosI; 1 past the critical
// angle.
double hechtReflectance(double cosI, double n1, double n2) {
  double sin2T = (n1 / n2) * (n1 / n2) * (1 - cosI * cosI);
  if (sin2T >= 1) return 1;
  double cosT = std::sqrt(1 - sin2T);
  double rs = (n1 * cosI - n2 * cosT) / (n1 * cosI + n2 * cosT);
  double rp = (n1 * cosT - n2 * cosI) / (n1 * cosT + n2 * cosI);
  return (rs * rs + rp * rp) / 2;
}

SurfaceInteraction planePoint() {
  return SurfaceInteraction(Point3f(0, 0, 0), Vector3f(), Point2f(0.5f, 0.5f), Vector3f(0, 0, 1),
                            Vector3f(1, 0, 0), Vector3f(0, 1, 0), Normal3f(), Normal3f(), 0, false);
}

Vector3f dir(double thetaDeg) {
  double t = thetaDeg * M_PI / 180;
  return Vector3f(Float(std::sin(t)), 0, Float(std::cos(t)));
}

struct Picks {
  int reflections = 0, transmissions = 0, failures = 0;
  double reflectionPdf = -1, transmissionPdf = -1;  // of the last pick of each
  Spectrum reflectionWeight, transmissionWeight;    // f |cos| / pdf, the last pick of each
};

// sampleF at n evenly spread values of the component value u1, the direction value fixed.
Picks pick(const BSDF& b, const Vector3f& wo, int n, int flags = kAllBxDF) {
  Picks p;
  for (int k = 0; k < n; ++k) {
    Vector3f wi;
    Float pdf = 0;
    BxDFType type;
    Float u1 = (Float(k) + 0.5f) / Float(n);
    Spectrum f = b.sampleF(wo, &wi, u1, Point2f(0.3f, 0.7f), &pdf, flags, &type);
    if (pdf == 0) {
      ++p.failures;
      continue;
    }
    Spectrum w = f * (std::abs(wi.z) / pdf);
    if (type & kReflection) {
      ++p.reflections;
      p.reflectionPdf = pdf;
      p.reflectionWeight = w;
    } else {
      ++p.transmissions;
      p.transmissionPdf = pdf;
      p.transmissionWeight = w;
    }
  }
  return p;
}

// pbrt's "glass" material, index 1.5, tinted kr and kt, at a point of the plane z = 0.
struct SmoothGlass {
  ConstantTexture<Spectrum> kr, kt;
  ConstantTexture<Float> index{1.5f};
  GlassMaterial glass{&kr, &kt, &index};
  MemoryArena arena;
  const BSDF* bsdf;
  explicit SmoothGlass(const Spectrum& r = Spectrum(1), const Spectrum& t = Spectrum(1))
      : kr(r), kt(t), bsdf(glass.getBSDF(planePoint(), arena)) {}
};

TEST(DielectricSampling, SmoothGlassReflectsWithTheFresnelProbability) {
  SmoothGlass g;
  const BSDF* b = g.bsdf;
  const int n = 100000;
  // From outside, and from inside below the critical angle (41.8 degrees).
  for (double theta : {0.0, 30.0, 60.0, 85.0, 150.0, 170.0}) {
    Vector3f wo = dir(theta);
    bool outside = wo.z > 0;
    double fr = outside ? hechtReflectance(wo.z, 1, 1.5) : hechtReflectance(-wo.z, 1.5, 1);
    Picks p = pick(*b, wo, n);
    EXPECT_EQ(p.failures, 0) << theta;
    // Evenly spread u1: the count is F n to within one.
    EXPECT_NEAR(p.reflections, fr * n, 1.5) << theta;
    EXPECT_NEAR(p.reflectionPdf, fr, 1e-5) << theta;
    EXPECT_NEAR(p.transmissionPdf, 1 - fr, 1e-5) << theta;
    // Each pick weighs its tint: 1 for reflection, the radiance scaling for refraction.
    double scaling = outside ? 1 / (1.5 * 1.5) : 1.5 * 1.5;
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(p.reflectionWeight[c], 1, 1e-4) << theta;
      EXPECT_NEAR(p.transmissionWeight[c], scaling, 1e-4 * scaling) << theta;
    }
  }
}

TEST(DielectricSampling, TotalInternalReflectionAlwaysReflects) {
  SmoothGlass g;
  const BSDF* b = g.bsdf;
  // Half-and-half picks lost every second path here (the refraction has nothing to give).
  Picks p = pick(*b, dir(180 - 45), 1000);
  EXPECT_EQ(p.reflections, 1000);
  EXPECT_EQ(p.failures, 0);
  EXPECT_NEAR(p.reflectionWeight[0], 1, 1e-5);
}

TEST(DielectricSampling, TintsWeighTheChoice) {
  SmoothGlass g(Spectrum(0.2f), Spectrum(1, 0.5f, 0));
  const BSDF* b = g.bsdf;
  Vector3f wo = dir(70);
  double fr = hechtReflectance(wo.z, 1, 1.5);
  double pr = fr * 0.2 / (fr * 0.2 + (1 - fr) * 0.5);
  Picks p = pick(*b, wo, 100000);
  EXPECT_NEAR(p.reflections, pr * 100000, 1.5);
  EXPECT_NEAR(p.reflectionPdf, pr, 1e-5);
  // The value over the pick's probability: r F / pr and t (1 - F) / (1 - pr) eta^-2.
  EXPECT_NEAR(p.reflectionWeight[0], 0.2 * fr / pr, 1e-4);
  EXPECT_NEAR(p.transmissionWeight[1], 0.5 * (1 - fr) / (1 - pr) / 2.25, 1e-4);
  EXPECT_EQ(p.transmissionWeight[2], 0);
}

TEST(DielectricSampling, FlagsForOneSideTakeThatComponentWhole) {
  // What the Whitted-style recursion asks for: one specular direction at a time, at pdf 1.
  SmoothGlass g;
  const BSDF* b = g.bsdf;
  Vector3f wo = dir(40);
  double fr = hechtReflectance(wo.z, 1, 1.5);
  Picks r = pick(*b, wo, 100, kSpecular | kReflection);
  Picks t = pick(*b, wo, 100, kSpecular | kTransmission);
  EXPECT_EQ(r.reflections, 100);
  EXPECT_EQ(t.transmissions, 100);
  EXPECT_EQ(r.reflectionPdf, 1);
  EXPECT_EQ(t.transmissionPdf, 1);
  EXPECT_NEAR(r.reflectionWeight[0], fr, 1e-5);
  EXPECT_NEAR(t.transmissionWeight[0], (1 - fr) / 2.25, 1e-5);
}

// A Lambertian reflection with a selection weight of the test's choosing.
class WeightedLambertian : public BxDF {
 public:
  WeightedLambertian(Float r, Float weight)
      : BxDF(BxDFType(kReflection | kDiffuse)), r_(r), weight_(weight) {}
  Spectrum f(const Vector3f&, const Vector3f&) const override { return Spectrum(r_ * kInvPi); }
  std::optional<Float> selectionWeight(const Vector3f&) const override { return weight_; }

 private:
  Float r_, weight_;
};

TEST(DielectricSampling, WeightedPicksOfSampledComponentsReportTheMixtureDensity) {
  // Two cosine-sampled components picked 1 : 3: the mixture density is still cos / pi, and
  // sampleF's density and value are pdf() and f() there.
  MemoryArena arena;
  BSDF b(planePoint());
  b.add(arena.make<WeightedLambertian>(0.2f, 1.f));
  b.add(arena.make<WeightedLambertian>(0.6f, 3.f));
  Vector3f wo = dir(30);
  int first = 0;
  const int n = 4000;
  for (int k = 0; k < n; ++k) {
    Float u1 = (Float(k) + 0.5f) / Float(n);
    Vector3f wi;
    Float pdf = 0;
    Spectrum f = b.sampleF(wo, &wi, u1, Point2f(0.25f, 0.6f), &pdf);
    ASSERT_GT(pdf, 0);
    EXPECT_NEAR(pdf, wi.z * kInvPi, 1e-6);
    EXPECT_NEAR(pdf, b.pdf(wo, wi), 1e-6);
    EXPECT_NEAR(f[0], 0.8f * kInvPi, 1e-6);
    // The two components draw the same direction from u2; u1's remainder is unused by them.
    if (u1 < 0.25f) ++first;
  }
  EXPECT_EQ(first, n / 4);
}

// A rough dielectric through its BSDF, untinted.
struct RoughGlass {
  MemoryArena arena;
  TrowbridgeReitzDistribution distribution;
  TrowbridgeReitzDielectric bxdf;
  BSDF bsdf;
  explicit RoughGlass(Float alpha, Float eta = 1.5f)
      : distribution(alpha, alpha),
        bxdf(Spectrum(1), Spectrum(1), &distribution, 1, eta),
        bsdf(planePoint(), eta) {
    bsdf.add(&bxdf);
  }
};

TEST(DielectricSampling, RoughDielectricSamplesWeighAtMostOne) {
  // Reflecting with the drawn microfacet's F and refracting otherwise, each sample's value over
  // its density is G / G1 (times the radiance scaling of a refraction), never above it: the
  // estimator half-and-half picks gave weighed up to 2 (1 - F) and 2F / F_macro.
  for (Float alpha : {0.01f, 0.1f, 0.4f, 1.f}) {
    RoughGlass g(alpha);
    EXPECT_TRUE(g.bsdf.readsComponentValue());
    for (double theta : {0.0, 40.0, 80.0, 89.0, 120.0, 160.0}) {
      Vector3f wo = dir(theta);
      double scaling = wo.z > 0 ? 1 / 2.25 : 2.25;
      int worst = 0, samples = 0;
      for (int i = 0; i < 64; ++i)
        for (int j = 0; j < 64; ++j) {
          Vector3f wi;
          Float pdf = 0;
          BxDFType type;
          Float uc = (Float((i * 37 + j * 11) % 64) + 0.5f) / 64;
          Spectrum f = g.bsdf.sampleF(wo, &wi, uc, Point2f((i + 0.5f) / 64, (j + 0.5f) / 64), &pdf,
                                      kAllBxDF, &type);
          if (pdf == 0) continue;
          ++samples;
          double w = f[0] * std::abs(wi.z) / pdf;
          double bound = (type & kTransmission) ? scaling : 1;
          if (w > bound * (1 + 1e-3)) ++worst;
        }
      EXPECT_GT(samples, 0) << alpha << " " << theta;
      EXPECT_EQ(worst, 0) << "alpha " << alpha << ", theta " << theta;
    }
  }
}

TEST(DielectricSampling, RoughDielectricReflectsWithTheMicrofacetsFresnel) {
  // A fixed direction value fixes the microfacet; over u1 the reflected share is its F.
  RoughGlass g(0.3f);
  Vector3f wo = dir(50);
  const int n = 20000;
  int reflected = 0;
  Vector3f wiR;
  for (int k = 0; k < n; ++k) {
    Vector3f wi;
    Float pdf = 0;
    BxDFType type;
    g.bsdf.sampleF(wo, &wi, (Float(k) + 0.5f) / Float(n), Point2f(0.6f, 0.2f), &pdf, kAllBxDF,
                   &type);
    ASSERT_GT(pdf, 0);
    if (type & kReflection) {
      ++reflected;
      wiR = wi;
    }
  }
  ASSERT_GT(reflected, 0);
  Vector3f wh = normalize(wo + wiR);
  double fr = hechtReflectance(dot(wo, wh), 1, 1.5);
  EXPECT_NEAR(reflected, fr * n, 2);
}

TEST(DielectricSampling, RoughDielectricSplitsItsAlbedoBySide) {
  // What photon maps and the irradiance cache ask a BSDF for: reflection and transmission apart,
  // which a BxDF modelling both sides gives by counting its samples on each side.
  RoughGlass g(0.2f);
  RNG rng(5);
  std::vector<Point2f> u = stratifiedSamples2D(128, rng);
  Vector3f wo = dir(60);
  Spectrum all = g.bsdf.rho(wo, u), r = g.bsdf.rho(wo, u, kAllReflection),
           t = g.bsdf.rho(wo, u, kAllTransmission);
  EXPECT_NEAR(r[0] + t[0], all[0], 1e-5);
  // The reflected share of a lightly rough interface is near the smooth one's F (0.089 at 60).
  EXPECT_NEAR(r[0], hechtReflectance(wo.z, 1, 1.5), 0.02);
  EXPECT_GT(t[0], 0.3);
}

}  // namespace
}  // namespace candela
