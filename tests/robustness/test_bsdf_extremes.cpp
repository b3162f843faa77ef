// BSDFs at the ends of their parameter ranges (issue 15): roughness 1e-7 and 1 for pbrt-v2's
// Blinn distribution (exponent 1 / roughness) and pbrt-v3's Trowbridge-Reitz (with and without
// remaproughness), refraction indices 1.0001 and 100, at 89.99 degrees incidence. Every sampled
// value and pdf is finite and non-negative, sampleF's pdf is pdf()'s, and the directional albedo
// (the mean of f |cos| / pdf) stays within the energy bound: 1 for reflection, (eta_o / eta_i)^2
// for transmission, which carries radiance across the interface (pbrt 3e §8.2.3). Then whole
// materials in a white furnace (an infinite light of radiance 1): with albedo <= 1 no pixel can
// exceed 1 in expectation, and the image is finite. Blinn at exponent 1e7 had an albedo of 1.39:
// f and pdf normalised the half vector differently, and cos^1e7 turned one float step of it into
// a factor 1.8 (reflection/microfacet_distribution.h).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>

#include "core/rng.h"
#include "reflection/fresnel.h"
#include "reflection/microfacet.h"
#include "reflection/microfacet_distribution.h"
#include "reflection/trowbridge_reitz.h"
#include "reflection/trowbridge_reitz_bxdfs.h"
#include "scene_files.h"
#include "support/render_scene.h"
#include "support/robustness_figures.h"

namespace candela {
namespace {

struct AlbedoEstimate {
  double mean = 0, sigma = 0;  // the estimate and its standard error
  long nonFinite = 0, pdfMismatch = 0, zeroPdf = 0;
};

// n samples of bxdf at wo: f |cos theta_i| / pdf, each checked; the mean over all n (a sample
// with pdf 0 counts as 0, as a renderer ends that path).
AlbedoEstimate albedo(const BxDF& bxdf, const Vector3f& wo, int n, uint64_t seed) {
  RNG rng(seed);
  AlbedoEstimate e;
  double sum = 0, sum2 = 0;
  for (int i = 0; i < n; ++i) {
    Float u0 = rng.uniformFloat(), u1 = rng.uniformFloat();
    Vector3f wi;
    Float pdf = 0;
    Spectrum f = bxdf.sampleF(wo, &wi, Point2f(u0, u1), &pdf);
    if (!std::isfinite(pdf) || pdf < 0 || !f.isFinite() || f.r() < 0) {
      ++e.nonFinite;
      continue;
    }
    if (pdf == 0 || f.isBlack()) {
      e.zeroPdf += pdf == 0;
      continue;
    }
    Float again = bxdf.pdf(wo, wi);
    if (!(std::abs(again - pdf) <= 1e-3f * pdf)) ++e.pdfMismatch;
    double x = double(f.r()) * std::abs(wi.z) / pdf;
    if (!std::isfinite(x)) ++e.nonFinite;
    sum += x;
    sum2 += x * x;
  }
  e.mean = sum / n;
  e.sigma = std::sqrt(std::max(0.0, sum2 / n - e.mean * e.mean) / n);
  return e;
}

struct BxdfCase {
  std::string name;
  std::function<const BxDF*(MemoryArena&)> make;
  double bound;  // the largest directional albedo energy allows
};

Vector3f incidence(double degrees, double azimuth) {
  double t = degrees * M_PI / 180;
  return Vector3f(Float(std::sin(t) * std::cos(azimuth)), Float(std::sin(t) * std::sin(azimuth)),
                  Float(std::cos(t)));
}

TEST(BsdfExtremes, MicrofacetSamplingAtGrazingIncidenceIsFiniteAndConservesEnergy) {
  static const FresnelNoOp white;
  std::vector<BxdfCase> cases;
  for (Float roughness : {1e-7f, 1.f})
    cases.push_back({"Blinn roughness " + std::to_string(roughness),
                     [roughness](MemoryArena& a) -> const BxDF* {
                       auto* d = a.make<BlinnDistribution>(1 / roughness);
                       return a.make<MicrofacetReflection>(Spectrum(1), &white, d);
                     },
                     1});
  for (bool remap : {false, true})
    for (Float roughness : {1e-7f, 1.f}) {
      Float alpha = remap ? roughnessToAlpha(roughness) : roughness;
      std::string tag =
          std::string(remap ? "remapped " : "") + "roughness " + std::to_string(roughness);
      cases.push_back({"Trowbridge-Reitz reflection " + tag,
                       [alpha](MemoryArena& a) -> const BxDF* {
                         auto* d = a.make<TrowbridgeReitzDistribution>(alpha, alpha);
                         return a.make<TrowbridgeReitzReflection>(Spectrum(1), &white, d);
                       },
                       1});
      for (Float eta : {1.0001f, 100.f})
        for (bool fromInside : {false, true}) {
          // From outside (wo above) light crosses into the index-eta side: radiance scales by
          // 1 / eta^2; from inside by eta^2.
          double bound = fromInside ? double(eta) * eta : 1 / (double(eta) * eta);
          cases.push_back({"Trowbridge-Reitz transmission eta " + std::to_string(eta) + " " + tag +
                               (fromInside ? " from inside" : ""),
                           [alpha, eta](MemoryArena& a) -> const BxDF* {
                             auto* d = a.make<TrowbridgeReitzDistribution>(alpha, alpha);
                             return a.make<TrowbridgeReitzTransmission>(Spectrum(1), d, 1, eta);
                           },
                           bound});
        }
    }
  const int n = 100000;
  double worstExcess = -1e30;
  for (const BxdfCase& c : cases)
    for (double degrees : {0.0, 60.0, 89.0, 89.99}) {
      MemoryArena arena;
      const BxDF* bxdf = c.make(arena);
      bool inside = c.name.find("from inside") != std::string::npos;
      Vector3f wo = incidence(degrees, 0.3);
      if (inside) wo.z = -wo.z;
      AlbedoEstimate e = albedo(*bxdf, wo, n, 7);
      SCOPED_TRACE(c.name + " at " + std::to_string(degrees) + " degrees");
      EXPECT_EQ(e.nonFinite, 0);
      EXPECT_EQ(e.pdfMismatch, 0);
      // One-sided, 5 standard errors (p = 3e-7 per case), plus float rounding of the sum.
      EXPECT_LE(e.mean, c.bound * (1 + 1e-5) + 5 * e.sigma) << "albedo " << e.mean;
      double excess = (e.mean - c.bound) / c.bound;
      std::printf("%-62s %6.2f deg: albedo %.6g (bound %.6g) +- %.2g, pdf 0: %ld\n", c.name.c_str(),
                  degrees, e.mean, c.bound, e.sigma, e.zeroPdf);
      worstExcess = std::max(worstExcess, excess);
    }
  test::recordFigure(
      "Blinn and Trowbridge-Reitz (roughness 1e-7, 1; eta 1.0001, 100) at 0..89.99 "
      "degrees, 100k samples each: finite, pdf consistent, albedo <= bound + 5 sigma",
      "largest albedo / bound - 1: %.2g", worstExcess);
}

// ---- Materials in a white furnace ---------------------------------------------------------------

struct FurnaceCase {
  std::string material;
  std::string integrator;  // empty: the scene's (pbrt-v2 "path", maxdepth 50)
};

TEST(BsdfExtremes, MaterialsInAWhiteFurnaceNeverExceedTheSky) {
  const std::string v3 = "Integrator \"path\" \"integer maxdepth\" [50]";
  // A white conductor: Fresnel reflectance 1 - 4e-6 at normal incidence.
  const std::string metal = "Material \"metal\" \"rgb eta\" [1 1 1] \"rgb k\" [1000 1000 1000] ";
  const std::string plastic = "Material \"plastic\" \"rgb Kd\" [.5 .5 .5] \"rgb Ks\" [.5 .5 .5] ";
  const std::string noRemap = " \"bool remaproughness\" \"false\"";
  const FurnaceCase cases[] = {
      {"Material \"glass\" \"float index\" [100]", ""},
      {"Material \"glass\" \"float index\" [1.0001]", ""},
      {plastic + "\"float roughness\" [1e-7]", ""},
      {plastic + "\"float roughness\" [1]", ""},
      {metal + "\"float roughness\" [1e-7]", ""},
      {metal + "\"float roughness\" [1]", ""},
      {"Material \"matte\" \"rgb Kd\" [0.999 0.999 0.999]",
       "SurfaceIntegrator \"path\" \"integer maxdepth\" [1000]"},
      {metal + "\"float roughness\" [1e-7]", v3},
      {metal + "\"float roughness\" [1e-7]" + noRemap, v3},
      {metal + "\"float roughness\" [1]" + noRemap, v3},
      {"Material \"glass\" \"float uroughness\" [1e-7] \"float vroughness\" [1e-7]" + noRemap, v3},
      {"Material \"glass\" \"float uroughness\" [1] \"float vroughness\" [1]" + noRemap, v3},
      {"Material \"glass\" \"float index\" [100] \"float uroughness\" [0.3] "
       "\"float vroughness\" [0.3]",
       v3},
      {"Material \"glass\" \"float index\" [1.0001] \"float uroughness\" [0.3] "
       "\"float vroughness\" [0.3]",
       v3},
  };
  double worstExcess = -1e30;
  for (const FurnaceCase& c : cases) {
    SCOPED_TRACE(c.material + " " + c.integrator);
    std::string text = test::robustnessScene("bsdf-furnace.pbrt");
    test::replaceOnce(&text, "Material \"glass\" \"float index\" [100]", c.material);
    if (!c.integrator.empty())
      test::replaceOnce(&text, "SurfaceIntegrator \"path\" \"integer maxdepth\" [50]",
                        c.integrator);
    test::RenderedScene r = test::renderSceneText(text);
    EXPECT_EQ(r.results.front().nonFiniteSamples, 0u);
    ImageBuffer image = r.film().image();
    double sum = 0, sum2 = 0;
    int n = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x)
        for (int ch = 0; ch < 3; ++ch, ++n) {
          double v = image.at(x, y, ch);
          ASSERT_TRUE(std::isfinite(v));
          sum += v;
          sum2 += v * v;
        }
    // The image mean's standard error is at most the pixels' spread / sqrt(n) (the spread also
    // holds the true differences between pixels); one-sided, 4 of them (p = 3e-5 per case).
    double mean = sum / n, sigma = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
    EXPECT_LE(mean, 1 + 4 * sigma + 1e-6);
    std::printf("%-100s %s: mean %.5f +- %.5f\n", c.material.c_str(),
                c.integrator.empty() ? "v2" : "v3", mean, sigma);
    worstExcess = std::max(worstExcess, (mean - 1) / std::max(sigma, 1e-9));
  }
  test::recordFigure(
      "14 materials (glass index 1.0001, 100; roughness 1e-7, 1; Kd 0.999 at "
      "maxdepth 1000) in a white furnace: finite, image mean <= 1 + 4 sigma",
      "largest (mean - 1) / sigma: %.2f", worstExcess);
}

}  // namespace
}  // namespace candela
