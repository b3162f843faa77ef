// Properties every BxDF must have (seed notes §25): pdfs integrate to 1, BRDFs are reciprocal,
// reflectance never exceeds 1 (by adaptive quadrature, deterministic), the Monte Carlo rho
// estimators agree with quadrature, and a lossless specular dielectric conserves energy.
#include <gtest/gtest.h>

#include <iomanip>
#include <iostream>

#include "bxdf_cases.h"
#include "core/sampling.h"
#include "direction_stats.h"

namespace candela {
namespace {

using testcases::BxDFCase;
using testcases::direction;
using testcases::makeCase;

// rho_hd(wo) = integral over wo's side (or the other side, for a BTDF) of f |cos theta_i|.
double albedo(const BxDF& b, const Vector3f& wo, int channel = 0) {
  bool below = (wo.z < 0) == ((b.type() & kReflection) != 0);
  double t0 = below ? M_PI / 2 : 0, t1 = below ? M_PI : M_PI / 2;
  // To ~1e-5 (relative 1e-5 and absolute 1e-7 per cell), ten times below the check's margin.
  return stats::integrateSphere(
      [&](const Vector3f& wi) { return double(b.f(wo, wi)[channel]) * std::abs(wi.z); }, 10, 20, t0,
      t1, 1e-5, 1e-7);
}

TEST(BxDFProperties, PdfIntegratesToOneWhereNoSampleIsLost) {
  // BxDFs whose sampling cannot leave wo's hemisphere, or practically never does (lobes far
  // narrower than the angle to the horizon); the others integrate to their success rate, which
  // the chi-square test checks.
  std::vector<BxDFCase> cases;
  cases.push_back(makeCase("Lambertian", direction(40), [](MemoryArena& a) {
    return a.make<LambertianReflection>(Spectrum(1));
  }));
  cases.push_back(makeCase("OrenNayar", direction(100),
                           [](MemoryArena& a) { return a.make<OrenNayar>(Spectrum(1), 45); }));
  cases.push_back(makeCase("Blinn1000_0", direction(0),
                           [](MemoryArena& a) { return testcases::blinnMicrofacet(a, 1000); }));
  cases.push_back(makeCase("Aniso300_1000_10", direction(10), [](MemoryArena& a) {
    return testcases::anisoMicrofacet(a, 300, 1000);
  }));
  cases.push_back(makeCase("FresnelBlend_0", direction(0), [](MemoryArena& a) {
    return a.make<FresnelBlend>(Spectrum(0.5f), Spectrum(0.5f), a.make<BlinnDistribution>(1000));
  }));
  cases.push_back(makeCase("Phong_20", direction(20),
                           [](MemoryArena& a) { return testcases::phongLafortune(a, 200); }));
  cases.push_back(makeCase("BTDF_Lambertian", direction(60), [](MemoryArena& a) {
    return a.make<BRDFToBTDF>(a.make<LambertianReflection>(Spectrum(1)));
  }));
  cases.push_back(makeCase("MERL", direction(70), [](MemoryArena& a) {
    return a.make<MeasuredBRDF>(&testcases::syntheticMerlTable());
  }));
  cases.push_back(makeCase("Irregular", direction(5), [](MemoryArena& a) {
    return a.make<IrregularMeasuredBRDF>(&testcases::syntheticIrregularTable());
  }));
  for (const BxDFCase& c : cases) {
    double integral =
        stats::integrateSphere([&](const Vector3f& wi) { return double(c.bxdf->pdf(c.wo, wi)); });
    EXPECT_NEAR(integral, 1, 0.01) << c.name;
  }
}

TEST(BxDFProperties, BRDFsAreReciprocal) {
  std::vector<BxDFCase> cases = testcases::sampledCases(false);
  cases.push_back(makeCase("FresnelBlendConductor", direction(0), [](MemoryArena& a) {
    return a.make<MicrofacetReflection>(Spectrum(1),
                                        a.make<FresnelConductor>(Spectrum(0.37f), Spectrum(2.82f)),
                                        a.make<AnisotropicDistribution>(20, 3));
  }));
  RNG rng(99);
  for (const BxDFCase& c : cases) {
    if (!c.isBRDF) continue;
    double worst = 0;
    for (int i = 0; i < 2000; ++i) {
      Float side = c.wo.z < 0 ? -1 : 1;
      Vector3f a = sampleUniformHemisphere(Point2f(rng.uniformFloat(), rng.uniformFloat()));
      Vector3f b = sampleUniformHemisphere(Point2f(rng.uniformFloat(), rng.uniformFloat()));
      a.z *= side;
      b.z *= side;
      Spectrum fab = c.bxdf->f(a, b), fba = c.bxdf->f(b, a);
      for (int k = 0; k < 3; ++k) {
        double scale = std::max(std::abs(fab[k]), std::abs(fba[k]));
        if (scale > 0) worst = std::max(worst, std::abs(fab[k] - fba[k]) / scale);
      }
    }
    // Float rounding only: the two orders compute the same quantities in a different order.
    EXPECT_LT(worst, 1e-4) << c.name;
  }
}

// The draft's Oren-Nayar is the qualitative model, which is not exactly energy conserving: with
// R = 1 its albedo exceeds 1 near grazing incidence for small sigma. By quadrature of the formula
// over (sigma, theta_o): at most 1.0151 (sigma 12 degrees, theta_o -> 90), 1.0063 at sigma 5,
// below 1 for sigma >= 20 at every angle and for every sigma up to theta_o = 60 degrees. The
// allowance is that known excess, no more, and only where it occurs.
double orenNayarExcess(double sigmaDeg, double thetaDeg) {
  if (sigmaDeg <= 0 || sigmaDeg >= 20 || thetaDeg <= 60) return 0;
  return 0.016;
}

// The albedo sweep over the parameters the issue names: roughness 1e-3..1, Fresnel of
// dielectrics with eta 1.0001..10 from outside and inside, a conductor, none; incidence from the
// normal to 89.9 degrees. Every run takes a corner subset; the Long suite the whole grid.
void albedoSweep(bool full) {
  std::vector<double> thetas =
      full ? std::vector<double>{0, 15, 30, 45, 60, 75, 85, 89.9} : std::vector<double>{0, 89.9};
  std::vector<Float> roughness =
      full ? std::vector<Float>{1e-3f, 1e-2f, 0.1f, 0.3f, 1} : std::vector<Float>{1e-3f, 1};
  std::vector<Float> etas =
      full ? std::vector<Float>{1.0001f, 1.333f, 1.5f, 2.42f, 10} : std::vector<Float>{1.5f};
  using Maker = std::function<const Fresnel*(MemoryArena&)>;
  struct NamedFresnel {
    std::string name;
    Maker make;
    bool spectral, sided;  // channels differ; the inside differs from the outside
  };
  std::vector<NamedFresnel> fresnels = {
      {"none", [](MemoryArena& a) { return a.make<FresnelNoOp>(); }, false, false},
      {"gold",
       [](MemoryArena& a) {
         return a.make<FresnelConductor>(Spectrum(0.37f, 0.3f, 1.4f), Spectrum(2.82f, 2.6f, 1.9f));
       },
       true, false}};
  for (Float eta : etas)
    fresnels.push_back({testcases::cat("eta", eta),
                        [eta](MemoryArena& a) { return a.make<FresnelDielectric>(1.f, eta); },
                        false, true});
  double worst = 0;
  std::string worstName;
  auto check = [&](const std::string& name, const BxDF& b, const Vector3f& wo, int channels,
                   double excess = 0) {
    for (int ch = 0; ch < channels; ++ch) {
      double rho = albedo(b, wo, ch) - excess;
      // 1e-4: the quadrature's tolerance, far below any physical excess.
      EXPECT_LE(rho, 1 + 1e-4) << name << " channel " << ch;
      EXPECT_GE(rho, 0) << name;
      if (excess == 0 && rho > worst) worst = rho, worstName = name;
    }
  };
  for (double t : thetas) {
    Vector3f wo = direction(t, 20), inside = direction(180 - t, 20);
    for (Float r : roughness)
      for (const NamedFresnel& fr : fresnels) {
        MemoryArena a;
        const Fresnel* f = fr.make(a);
        BlinnDistribution blinn(1 / r);
        AnisotropicDistribution aniso(1 / r, 0.2f / r);
        int ch = fr.spectral ? 3 : 1;
        for (const Vector3f& w : {wo, inside}) {
          if (w.z < 0 && !fr.sided) continue;
          std::string tag = testcases::cat(fr.name, "_r", r, "_theta", t, w.z < 0 ? "_inside" : "");
          check(testcases::cat("Blinn_", tag), MicrofacetReflection(Spectrum(1), f, &blinn), w, ch);
          check(testcases::cat("Aniso_", tag), MicrofacetReflection(Spectrum(1), f, &aniso), w, ch);
        }
      }
    std::vector<std::pair<Float, Float>> coats = {{1.f, 0.f}, {0.9f, 0.04f}};
    if (full) coats.insert(coats.end(), {{0.5f, 0.5f}, {0.f, 1.f}});
    for (Float r : roughness)
      for (auto [rd, rs] : coats) {
        BlinnDistribution blinn(1 / r);
        AnisotropicDistribution aniso(1 / r, 0.2f / r);
        std::string tag = testcases::cat(rd, "_", rs, "_r", r, "_theta", t);
        check(testcases::cat("FresnelBlendBlinn_", tag),
              FresnelBlend(Spectrum(rd), Spectrum(rs), &blinn), wo, 1);
        check(testcases::cat("FresnelBlendAniso_", tag),
              FresnelBlend(Spectrum(rd), Spectrum(rs), &aniso), wo, 1);
      }
    for (Float sigma :
         full ? std::vector<Float>{0, 5, 10, 12, 15, 20, 30, 60, 90} : std::vector<Float>{20, 90})
      check(testcases::cat("OrenNayar_", sigma, "_theta", t), OrenNayar(Spectrum(1), sigma), wo, 1,
            orenNayarExcess(sigma, t));
    LafortuneFit clay = *lafortuneFit("clay");
    check(testcases::cat("Clay_theta", t), Lafortune(clay.diffuse, clay.lobes), wo, 3);
    check(testcases::cat("Lambertian_theta", t), LambertianReflection(Spectrum(1)), wo, 1);
  }
  std::cout << std::setprecision(8) << "largest albedo (Oren-Nayar's excess aside) " << worst
            << " (" << worstName << ")\n";
}

TEST(BxDFProperties, OrenNayarAlbedoMatchesAnIndependentQuadrature) {
  // Albedo of the qualitative model with R = 1, integrated separately in (theta_i) with the phi
  // integral of max(0, cos) done by hand (2): sigma 10 at 89.9 degrees exceeds 1 (the model's
  // known excess), sigma 20 at 60 and sigma 45 at 30 do not.
  EXPECT_NEAR(albedo(OrenNayar(Spectrum(1), 10), direction(89.9)), 1.014580, 2e-4);
  EXPECT_NEAR(albedo(OrenNayar(Spectrum(1), 20), direction(60)), 0.942331, 2e-4);
  EXPECT_NEAR(albedo(OrenNayar(Spectrum(1), 45), direction(30)), 0.722023, 2e-4);
}

TEST(BxDFProperties, AlbedoAtMostOne) { albedoSweep(false); }
TEST(LongBxDFProperties, AlbedoAtMostOneFullSweep) { albedoSweep(true); }

// A BxDF with no closed-form rho: the base class's Monte Carlo estimators run.
class PlainLambertian : public BxDF {
 public:
  explicit PlainLambertian(Float r) : BxDF(BxDFType(kReflection | kDiffuse)), r_(r) {}
  Spectrum f(const Vector3f&, const Vector3f&) const override { return Spectrum(r_ * kInvPi); }

 private:
  Float r_;
};

TEST(BxDFProperties, MonteCarloRhoAgreesWithQuadrature) {
  // Each single-sample estimate is rho with one sample; their spread gives the standard error of
  // plain Monte Carlo, which bounds the stratified estimate's. Agreement within 5 standard errors
  // (two-sided p = 6e-7 per check under normality) plus the quadrature's 1e-4.
  std::vector<BxDFCase> cases;
  cases.push_back(makeCase("OrenNayar", direction(50),
                           [](MemoryArena& a) { return a.make<OrenNayar>(Spectrum(0.8f), 40); }));
  cases.push_back(makeCase("Blinn10", direction(45),
                           [](MemoryArena& a) { return testcases::blinnMicrofacet(a, 10); }));
  cases.push_back(makeCase("Aniso", direction(70, 30),
                           [](MemoryArena& a) { return testcases::anisoMicrofacet(a, 50, 5); }));
  cases.push_back(makeCase("FresnelBlend", direction(20), [](MemoryArena& a) {
    return a.make<FresnelBlend>(Spectrum(0.5f), Spectrum(0.3f), a.make<BlinnDistribution>(30));
  }));
  cases.push_back(makeCase("Clay", direction(60), testcases::clay));
  cases.push_back(makeCase("BTDF", direction(30), [](MemoryArena& a) {
    return a.make<BRDFToBTDF>(testcases::blinnMicrofacet(a, 20));
  }));
  RNG rng(123);
  for (const BxDFCase& c : cases) {
    const int n = 64;
    std::vector<Point2f> u = stratifiedSamples2D(n, rng);
    double sum = 0, sum2 = 0;
    for (const Point2f& s : u) {
      double v = c.bxdf->rho(c.wo, std::span<const Point2f>(&s, 1))[0];
      sum += v;
      sum2 += v * v;
    }
    double mean = sum / u.size(), var = std::max(0.0, sum2 / u.size() - mean * mean);
    double se = std::sqrt(var / u.size());
    double estimate = c.bxdf->rho(c.wo, u)[0], exact = albedo(*c.bxdf, c.wo);
    EXPECT_NEAR(estimate, exact, 5 * se + 1e-4) << c.name << " se " << se;
    EXPECT_NEAR(rhoStratified(*c.bxdf, c.wo, n, rng)[0], exact, 5 * se + 1e-4) << c.name;
  }
  // rho_hh of f = r / pi is r; the draft's 2 pi for the uniform pdf would give r / (4 pi^2).
  PlainLambertian plain(0.7f);
  double sum = 0, sum2 = 0;
  const int n = 64;
  std::vector<Point2f> u1 = stratifiedSamples2D(n, rng), u2 = stratifiedSamples2D(n, rng);
  for (size_t i = 0; i < u1.size(); ++i) {
    double v =
        plain.rho(std::span<const Point2f>(&u1[i], 1), std::span<const Point2f>(&u2[i], 1))[0];
    sum += v;
    sum2 += v * v;
  }
  double mean = sum / u1.size();
  double se = std::sqrt(std::max(0.0, sum2 / u1.size() - mean * mean) / u1.size());
  EXPECT_NEAR(plain.rho(u1, u2)[0], 0.7, 5 * se);
  EXPECT_NEAR(plain.rho(direction(30), u1)[0], 0.7, 1e-6);  // cosine sampling: constant weights
}

TEST(BxDFProperties, LosslessSpecularDielectricConservesEnergy) {
  // R + T = 1 where T is the transmitted power: the radiance weight (eta_o / eta_i)^2 (1 - F)
  // times (eta_i / eta_o)^2. Also Stokes: F seen from outside at theta equals F from inside at
  // the refracted angle.
  for (Float eta : {1.0001f, 1.01f, 1.333f, 1.5f, 2.42f, 10.f}) {
    FresnelDielectric fr(1, eta);
    SpecularReflection refl(Spectrum(1), &fr);
    SpecularTransmission trans(Spectrum(1), 1, eta);
    for (double t : {0.0, 10.0, 30.0, 45.0, 60.0, 75.0, 85.0, 89.0, 89.9}) {
      for (double side : {t, 180 - t}) {
        Vector3f wo = direction(side, 10), wi;
        Float pdfR = 0, pdfT = 0;
        Spectrum r = refl.sampleF(wo, &wi, Point2f(), &pdfR);
        r *= absCosTheta(wi);
        Spectrum tw = trans.sampleF(wo, &wi, Point2f(), &pdfT);
        Float etaO = wo.z > 0 ? 1 : eta, etaI = wo.z > 0 ? eta : 1;
        Float t2 = pdfT > 0 ? tw[0] * absCosTheta(wi) * (etaI / etaO) * (etaI / etaO) : 0;
        EXPECT_NEAR(r[0] + t2, 1, 0.01) << "eta " << eta << " theta " << side;
        EXPECT_NEAR(r[0] + t2, 1, 1e-5) << "eta " << eta << " theta " << side;
        EXPECT_LE(refl.rho(wo, {})[0], 1);
        EXPECT_NEAR(refl.rho(wo, {})[0], r[0], 1e-6f);
        if (pdfT > 0) {
          EXPECT_NEAR(trans.rho(wo, {})[0], tw[0] * absCosTheta(wi), 1e-5f);
          // Away from grazing, where F's slope makes float rounding of the angles visible; the
          // inside angle's sin^2 is multiplied by eta^2 on the way out, and so is its rounding.
          if (std::min(absCosTheta(wo), absCosTheta(wi)) > 0.05f) {
            EXPECT_NEAR(fr.evaluate(wo.z)[0], fr.evaluate(wi.z)[0], 2e-5f + 2e-6f * eta * eta)
                << "eta " << eta << " theta " << side;
          }
        } else {
          EXPECT_NEAR(r[0], 1, 1e-6) << "total internal reflection";
        }
      }
    }
  }
}

}  // namespace
}  // namespace candela
