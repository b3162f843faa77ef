// Type flags, closed forms and edge cases of the BxDFs (lrt draft ch. 9; seed notes §24-25).
#include <gtest/gtest.h>

#include "core/memory.h"
#include "core/rng.h"
#include "reflection/brdf_to_btdf.h"
#include "reflection/bsdf.h"
#include "reflection/fresnel_blend.h"
#include "reflection/lafortune.h"
#include "reflection/microfacet.h"
#include "reflection/oren_nayar.h"
#include "reflection/specular.h"

namespace candela {
namespace {

Vector3f dir(Float thetaDeg, Float phiDeg) {
  Float t = radians(thetaDeg), p = radians(phiDeg);
  return Vector3f(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
}

TEST(BxDFs, EachHasOneSideAndOneKind) {
  FresnelNoOp noOp;
  BlinnDistribution blinn(10);
  LambertianReflection lambert(Spectrum(0.5f));
  OrenNayar on(Spectrum(0.5f), 20);
  SpecularReflection mirror(Spectrum(1), &noOp);
  SpecularTransmission glass(Spectrum(1), 1, 1.5f);
  MicrofacetReflection micro(Spectrum(1), &noOp, &blinn);
  FresnelBlend blend(Spectrum(0.5f), Spectrum(0.1f), &blinn);
  LafortuneFit clay = *lafortuneFit("clay");
  Lafortune laf(clay.diffuse, clay.lobes);
  BRDFToBTDF btdf(&micro), btdfDiffuse(&lambert);
  EXPECT_EQ(lambert.type(), kReflection | kDiffuse);
  EXPECT_EQ(on.type(), kReflection | kDiffuse);
  EXPECT_EQ(mirror.type(), kReflection | kSpecular);
  EXPECT_EQ(glass.type(), kTransmission | kSpecular);
  EXPECT_EQ(micro.type(), kReflection | kGlossy);
  EXPECT_EQ(blend.type(), kReflection | kGlossy);
  EXPECT_EQ(laf.type(), kReflection | kGlossy);
  EXPECT_EQ(btdf.type(), kTransmission | kGlossy);
  EXPECT_EQ(btdfDiffuse.type(), kTransmission | kDiffuse);
  EXPECT_TRUE(glass.matches(kAllTransmission));
  EXPECT_FALSE(glass.matches(kAllReflection));
  EXPECT_FALSE(mirror.matches(kAllBxDF & ~kSpecular));
}

TEST(BxDFs, LambertianIsRoverPiWithReflectanceR) {
  LambertianReflection l(Spectrum(0.2f, 0.5f, 0.9f));
  EXPECT_NEAR(l.f(dir(10, 0), dir(70, 100))[1], 0.5f / kPi, 1e-7f);
  EXPECT_EQ(l.rho(dir(30, 0), {}), Spectrum(0.2f, 0.5f, 0.9f));
  EXPECT_EQ(l.rho(std::span<const Point2f>(), std::span<const Point2f>()),
            Spectrum(0.2f, 0.5f, 0.9f));
}

TEST(BxDFs, OrenNayarTakesSigmaInDegrees) {
  // sigma = 20 degrees = 0.349066 rad: A = 1 - s^2 / (2 (s^2 + 0.33)) = 0.865168,
  // B = 0.45 s^2 / (s^2 + 0.09) = 0.258824; at normal incidence and exitance f = A / pi
  // = 0.275391 (the draft converted an uninitialised copy of sigma, seed notes §24).
  OrenNayar on(Spectrum(1), 20);
  EXPECT_NEAR(on.a(), 0.865168f, 1e-6f);
  EXPECT_NEAR(on.b(), 0.258824f, 1e-6f);
  EXPECT_NEAR(on.f(Vector3f(0, 0, 1), Vector3f(0, 0, 1))[0], 0.275391f, 1e-6f);
  // Retro-reflection at 60/60 degrees, same azimuth: f = (A + B sin 60 tan 60) / pi.
  Float s60 = std::sin(radians(60)), t60 = std::tan(radians(60));
  EXPECT_NEAR(on.f(dir(60, 0), dir(60, 0))[0], (0.865168f + 0.258824f * s60 * t60) / kPi, 1e-5f);
  // sigma = 0 is Lambertian.
  OrenNayar smooth(Spectrum(1), 0);
  EXPECT_NEAR(smooth.f(dir(50, 0), dir(20, 90))[0], kInvPi, 1e-7f);
  // Grazing on both sides and the pole stay finite.
  EXPECT_TRUE(on.f(Vector3f(1, 0, 0), Vector3f(0, 1, 0)).isFinite());
  EXPECT_TRUE(on.f(Vector3f(0, 0, 1), dir(89.99f, 0)).isFinite());
}

TEST(BxDFs, SpecularReflectionMirrorsWithFresnelWeight) {
  FresnelDielectric glass(1, 1.5f);
  SpecularReflection r(Spectrum(0.8f), &glass);
  Vector3f wi;
  Float pdf = 0;
  Vector3f wo = dir(60, 30);
  Spectrum v = r.sampleF(wo, &wi, Point2f(0.5f, 0.5f), &pdf);
  EXPECT_EQ(pdf, 1);
  EXPECT_NEAR(wi.x, -wo.x, 1e-7f);
  EXPECT_NEAR(wi.y, -wo.y, 1e-7f);
  EXPECT_NEAR(wi.z, wo.z, 1e-7f);
  // The delta's weight times |cos| is R F(60 degrees) = 0.8 * 0.0891867.
  EXPECT_NEAR(v[0] * absCosTheta(wi), 0.8f * 0.0891867f, 1e-6f);
  EXPECT_NEAR(r.rho(wo, {})[0], 0.8f * 0.0891867f, 1e-6f);
  EXPECT_TRUE(r.f(wo, wi).isBlack());
  EXPECT_EQ(r.pdf(wo, wi), 0);
}

TEST(BxDFs, SpecularTransmissionFollowsSnellAndScalesRadiance) {
  SpecularTransmission t(Spectrum(1), 1, 1.5f);
  Vector3f wi;
  Float pdf = 0;
  // Entering at 60 degrees: sin theta_t = sin 60 / 1.5, on the other side, opposite azimuth.
  Vector3f wo = dir(60, 30);
  Spectrum v = t.sampleF(wo, &wi, Point2f(), &pdf);
  ASSERT_EQ(pdf, 1);
  EXPECT_LT(wi.z, 0);
  EXPECT_NEAR(sinTheta(wi), std::sin(radians(60)) / 1.5f, 1e-6f);
  EXPECT_NEAR(wi.length(), 1, 1e-6f);
  EXPECT_LT(wi.x * wo.x, 0);
  // Radiance arriving from inside is scaled by (1 / 1.5)^2 and by 1 - F.
  EXPECT_NEAR(v[0] * absCosTheta(wi), (1 - 0.0891867f) / 2.25f, 1e-6f);
  // From inside past the critical angle: nothing is transmitted.
  Spectrum none = t.sampleF(dir(135, 0), &wi, Point2f(), &pdf);
  EXPECT_EQ(pdf, 0);
  EXPECT_TRUE(none.isBlack());
  EXPECT_TRUE(t.rho(dir(135, 0), {}).isBlack());
  // From inside below the critical angle the scale is 1.5^2.
  Vector3f inside = dir(160, 0);
  v = t.sampleF(inside, &wi, Point2f(), &pdf);
  ASSERT_EQ(pdf, 1);
  EXPECT_GT(wi.z, 0);
  Float f = fresnelDielectric(cosTheta(inside), 1, 1.5f);
  EXPECT_NEAR(v[0] * absCosTheta(wi), 2.25f * (1 - f), 1e-5f);
}

TEST(BxDFs, BRDFToBTDFMirrorsTheSecondDirection) {
  BlinnDistribution blinn(20);
  FresnelNoOp noOp;
  MicrofacetReflection m(Spectrum(1), &noOp, &blinn);
  BRDFToBTDF t(&m);
  Vector3f wo = dir(30, 0), wi = dir(140, 200);
  EXPECT_EQ(t.f(wo, wi), m.f(wo, otherHemisphere(wi)));
  EXPECT_EQ(t.pdf(wo, wi), m.pdf(wo, otherHemisphere(wi)));
  Vector3f sampled;
  Float pdf;
  BxDFType type;
  t.sampleF(wo, &sampled, Point2f(0.2f, 0.7f), &pdf, &type);
  EXPECT_LT(sampled.z, 0);
  EXPECT_EQ(type, kTransmission | kGlossy);
}

TEST(BxDFs, LafortunePhongLobePeaksAtTheMirrorDirection) {
  // (-1, -1, 1) with exponent e: at the mirror direction the lobe is (wo . wo)^e = 1.
  LafortuneLobe lobe{Spectrum(-1), Spectrum(-1), Spectrum(1), Spectrum(30)};
  Lafortune l(Spectrum(0.3f), std::span<const LafortuneLobe>(&lobe, 1));
  Vector3f wo = dir(40, 10);
  EXPECT_NEAR(l.f(wo, reflectAboutNormal(wo))[0], 0.3f / kPi + 1, 1e-5f);
  // Off the mirror direction: cos^30 of the angle to it.
  Vector3f wi = dir(50, 190);
  Float c = dot(reflectAboutNormal(wo), wi);
  EXPECT_NEAR(l.f(wo, wi)[0], 0.3f / kPi + std::pow(c, 30.f), 1e-5f);
  // Reciprocal, and a negative lobe base gives zero rather than NaN.
  EXPECT_NEAR(l.f(wi, wo)[0], l.f(wo, wi)[0], 1e-6f);
  EXPECT_NEAR(l.f(wo, wo)[0],
              0.3f / kPi + std::pow(std::max(0.f, -wo.x * wo.x - wo.y * wo.y + wo.z * wo.z), 30.f),
              1e-6f);
  EXPECT_FALSE(l.f(dir(80, 0), dir(80, 0)).hasNaN());
}

TEST(BxDFs, LafortuneFitsFromTheDraft) {
  std::optional<LafortuneFit> clay = lafortuneFit("clay");
  ASSERT_TRUE(clay.has_value());
  EXPECT_EQ(clay->lobes.size(), 3u);
  EXPECT_NEAR(clay->diffuse[0], 0.383626f, 1e-7f);
  EXPECT_NEAR(clay->lobes[2].exponent[2], 201.046802f, 1e-4f);
  // Named in the draft without coefficients: not available.
  for (const char* name : {"felt", "primer", "skin", "bluepaint", "brushedmetal", "unknown"})
    EXPECT_FALSE(lafortuneFit(name).has_value()) << name;
  Lafortune l(clay->diffuse, clay->lobes);
  for (Float t : {0.f, 30.f, 60.f, 89.f}) {
    Spectrum f = l.f(dir(t, 0), dir(t, 180));
    EXPECT_TRUE(f.isFinite());
    EXPECT_GE(f.maxComponent(), clay->diffuse[2] / kPi);
  }
}

TEST(BxDFs, FresnelBlendMatchesAshikhminShirley) {
  // Normal incidence and exitance with Blinn e = 10: diffuse = 28/(23 pi) Rd (1 - Rs)
  // (1 - 0.5^5)^2, specular = (e + 1)/(2 pi) / (4 * 1 * 1) * Rs (Schlick at cos 1 is Rs).
  BlinnDistribution blinn(10);
  FresnelBlend b(Spectrum(0.5f), Spectrum(0.05f), &blinn);
  Float diffuse = 28 / (23 * kPi) * 0.5f * 0.95f * (1 - 1 / 32.f) * (1 - 1 / 32.f);
  Float specular = 11 / (2 * kPi) / 4 * 0.05f;
  EXPECT_NEAR(b.f(Vector3f(0, 0, 1), Vector3f(0, 0, 1))[0], diffuse + specular, 1e-6f);
  EXPECT_NEAR(b.schlickFresnel(0)[0], 1, 1e-7f);
  EXPECT_NEAR(b.schlickFresnel(1)[0], 0.05f, 1e-7f);
}

TEST(BxDFs, TrigonometryIsSafeAtThePole) {
  Vector3f n(0, 0, 1);
  EXPECT_EQ(cosPhi(n), 1);
  EXPECT_EQ(sinPhi(n), 0);
  EXPECT_EQ(sin2Theta(Vector3f(0, 0, 1.0000001f)), 0);
  EXPECT_NEAR(cosPhi(dir(30, 60)), 0.5f, 1e-6f);
}

TEST(BSDF, SumsReflectancesAndUsesTheGeometricNormal) {
  SurfaceInteraction si;
  si.n = si.shading.n = Normal3f(0, 0, 1);
  si.shading.dpdu = Vector3f(1, 0, 0);
  MemoryArena arena;
  BSDF* b = arena.make<BSDF>(si);
  b->add(arena.make<LambertianReflection>(Spectrum(0.25f)));
  b->add(arena.make<BRDFToBTDF>(arena.make<LambertianReflection>(Spectrum(0.5f))));
  EXPECT_EQ(b->rho(Vector3f(0, 0, 1), {}), Spectrum(0.75f));
  EXPECT_EQ(b->rho(Vector3f(0, 0, 1), {}, kAllReflection), Spectrum(0.25f));
  // Same side of the geometric normal: reflection only; opposite sides: transmission only.
  EXPECT_NEAR(b->f(dir(10, 0), dir(20, 0))[0], 0.25f / kPi, 1e-7f);
  EXPECT_NEAR(b->f(dir(10, 0), dir(160, 0))[0], 0.5f / kPi, 1e-7f);
  // The mixture pdf averages over the matching components.
  EXPECT_NEAR(b->pdf(dir(10, 0), dir(20, 0)), 0.5f * std::cos(radians(20)) / kPi, 1e-6f);
  EXPECT_NEAR(b->pdf(dir(10, 0), dir(20, 0), kAllReflection), std::cos(radians(20)) / kPi, 1e-6f);
}

// A BSDF whose only component was added as a LambertianReflection takes its closed-form path; it
// must give the general mixture's results bit for bit, for directions on either side of a
// geometric normal tilted from the shading one, wo in the shading plane, and every flag set.
TEST(BSDF, LoneLambertianGivesTheMixturesResultsExactly) {
  SurfaceInteraction si;
  si.n = Normal3f(0, 0, 1);
  si.shading.n = normalize(Normal3f(0.3f, 0.1f, 1));
  si.shading.dpdu = Vector3f(1, 0, 0);
  MemoryArena arena;
  const LambertianReflection* lambert =
      arena.make<LambertianReflection>(Spectrum(0.2f, 0.5f, 0.9f));
  BSDF* closedForm = arena.make<BSDF>(si);
  closedForm->add(lambert);
  BSDF* mixture = arena.make<BSDF>(si);
  mixture->add(static_cast<const BxDF*>(lambert));
  RNG rng(11);
  auto sphere = [&] {
    Float z = 1 - 2 * rng.uniformFloat(), phi = 2 * kPi * rng.uniformFloat();
    Float r = std::sqrt(std::max(Float(0), 1 - z * z));
    return Vector3f(r * std::cos(phi), r * std::sin(phi), z);
  };
  Vector3f ns(si.shading.n);
  Vector3f inShadingPlane(ns.z, 0, -ns.x);  // dot with ns is exactly 0
  const int flagSets[] = {kAllBxDF,         kAllBxDF & ~kSpecular,   kAllReflection,
                          kAllTransmission, kReflection | kSpecular, kReflection | kDiffuse};
  int sampledBoth = 0, reflectedOnlyByShading = 0;
  for (int i = 0; i < 4000; ++i) {
    Vector3f wo = i == 0 ? inShadingPlane : sphere(), wi = sphere();
    Point2f u(rng.uniformFloat(), rng.uniformFloat());
    for (int flags : flagSets) {
      EXPECT_EQ(closedForm->numComponents(flags), mixture->numComponents(flags));
      EXPECT_EQ(closedForm->f(wo, wi, flags), mixture->f(wo, wi, flags));
      EXPECT_EQ(closedForm->pdf(wo, wi, flags), mixture->pdf(wo, wi, flags));
      Vector3f wiA(7, 7, 7), wiB(7, 7, 7);
      Float pdfA = -1, pdfB = -1;
      BxDFType typeA = kSpecular, typeB = kSpecular;
      Spectrum fA = closedForm->sampleF(wo, &wiA, 0.5f, u, &pdfA, flags, &typeA);
      Spectrum fB = mixture->sampleF(wo, &wiB, 0.5f, u, &pdfB, flags, &typeB);
      ASSERT_EQ(fA, fB) << i << " " << flags;
      ASSERT_EQ(pdfA, pdfB) << i << " " << flags;
      ASSERT_EQ(wiA, wiB) << i << " " << flags;
      ASSERT_EQ(typeA, typeB) << i << " " << flags;
      sampledBoth += pdfA > 0;
      reflectedOnlyByShading += pdfA > 0 && fA.isBlack();
    }
  }
  // Both outcomes of Veach's geometric-normal test were exercised.
  EXPECT_GT(sampledBoth, 1000);
  EXPECT_GT(reflectedOnlyByShading, 0);
}

// A lone Lambertian made with its own frame (BSDF(si, lambertian)) is the one made with dp/du's
// frame turned about the shading normal: the same values and densities, and sampled directions at
// the same angle to the normal and the same density; the frame is orthonormal and right-handed.
TEST(BSDF, LoneLambertianInItsOwnFrameIsTheSameAboutTheNormal) {
  RNG rng(23);
  auto sphere = [&] {
    Float z = 1 - 2 * rng.uniformFloat(), phi = 2 * kPi * rng.uniformFloat();
    Float r = std::sqrt(std::max(Float(0), 1 - z * z));
    return Vector3f(r * std::cos(phi), r * std::sin(phi), z);
  };
  MemoryArena arena;
  const LambertianReflection* lambert =
      arena.make<LambertianReflection>(Spectrum(0.7f, 0.4f, 0.1f));
  int sampled = 0;
  for (int i = 0; i < 2000; ++i) {
    SurfaceInteraction si;
    // Normals all round, straight down (the frame's one special case) among them.
    Vector3f n = i == 0 ? Vector3f(0, 0, -1) : i == 1 ? Vector3f(0, 0, 1) : sphere();
    si.n = Normal3f(normalize(n + sphere() * Float(0.2)));
    si.shading.n = Normal3f(n);
    si.shading.dpdu = sphere();
    const BSDF* own = arena.make<BSDF>(si, lambert);
    BSDF* gramSchmidt = arena.make<BSDF>(si);
    gramSchmidt->add(lambert);
    ASSERT_EQ(own->numComponents(), 1);
    Vector3f s = own->localToWorld(Vector3f(1, 0, 0)), t = own->localToWorld(Vector3f(0, 1, 0));
    EXPECT_NEAR(s.length(), 1, 1e-5f);
    EXPECT_NEAR(t.length(), 1, 1e-5f);
    EXPECT_NEAR(dot(s, t), 0, 1e-5f);
    EXPECT_NEAR(dot(s, n), 0, 1e-5f);
    EXPECT_NEAR(dot(cross(s, t), n), 1, 1e-5f) << i;
    Vector3f wo = sphere(), wi = sphere();
    EXPECT_EQ(own->f(wo, wi), gramSchmidt->f(wo, wi));
    EXPECT_EQ(own->pdf(wo, wi), gramSchmidt->pdf(wo, wi));
    Point2f u(rng.uniformFloat(), rng.uniformFloat());
    Vector3f wiA, wiB;
    Float pdfA = -1, pdfB = -1;
    Spectrum fA = own->sampleF(wo, &wiA, 0.5f, u, &pdfA);
    Spectrum fB = gramSchmidt->sampleF(wo, &wiB, 0.5f, u, &pdfB);
    EXPECT_EQ(pdfA, pdfB) << i;
    if (pdfA == 0) continue;
    ++sampled;
    EXPECT_NEAR(dot(wiA, n), dot(wiB, n), 1e-5f) << i;
    EXPECT_NEAR(wiA.length(), 1, 1e-5f);
    // Each value is its BSDF's for the direction it sampled (the azimuths differ, so the
    // geometric normal's test may part them).
    EXPECT_EQ(fA, own->f(wo, wiA)) << i;
    EXPECT_EQ(fB, gramSchmidt->f(wo, wiB)) << i;
  }
  EXPECT_GT(sampled, 1900);
}

}  // namespace
}  // namespace candela
