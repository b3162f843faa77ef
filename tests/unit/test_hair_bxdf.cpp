// The hair BxDF's deterministic properties: what of reciprocity the model keeps (and that it
// does not keep more), and that the colour parameterisation darkens monotonically.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/rng.h"
#include "core/sampling.h"
#include "reflection/hair_absorption.h"
#include "reflection/hair_bxdf.h"

namespace candela {
namespace {

// Longitudinal angle theta to the fibre's normal plane (x is the fibre) and azimuth phi from y.
Vector3f fibreDirection(double theta, double phi) {
  return Vector3f(Float(std::sin(theta)), Float(std::cos(theta) * std::cos(phi)),
                  Float(std::cos(theta) * std::sin(phi)));
}

// S(wo, wi) = f |w_i.z|, the quantity the model defines.
Spectrum scattering(const HairBxDF& b, const Vector3f& wo, const Vector3f& wi) {
  return b.f(wo, wi) * std::abs(wi.z);
}

double relativeDifference(const Spectrum& a, const Spectrum& b) {
  double d = 0;
  for (int i = 0; i < 3; ++i)
    d = std::max(d, std::abs(double(a[i]) - b[i]) / std::max(1e-30, double(std::max(a[i], b[i]))));
  return d;
}

TEST(HairBxDF, ReciprocalAtTheFibreCentreWithoutTiltForMirroredElevations) {
  // At h = 0 with alpha = 0, every factor is symmetric when |theta_i| = |theta_o|: Mp is, Ap and
  // the refracted path depend on theta_o only through its cosine and sin^2, and Np is even about
  // its shift p pi.
  HairBxDF b(0, 1.55f, hair::sigmaAFromConcentration(1.3f, 0.2f), 0.3f, 0.4f, 0);
  int checked = 0;
  for (double theta : {-1.2, -0.5, 0.2, 0.9})
    for (double sign : {-1.0, 1.0})
      for (double phiO : {0.3, 2.0})
        for (double phiI : {-2.5, -0.1, 1.0, 3.0}) {
          Vector3f wo = fibreDirection(theta, phiO), wi = fibreDirection(sign * theta, phiI);
          Spectrum a = scattering(b, wo, wi), c = scattering(b, wi, wo);
          ASSERT_GT(a.maxComponent(), 0);
          // Float evaluation of the same factors in another order.
          EXPECT_LT(relativeDifference(a, c), 1e-4) << theta << " " << phiO << " " << phiI;
          ++checked;
        }
  EXPECT_EQ(checked, 64);
}

// The largest relative asymmetry of S over a set of direction pairs.
double largestAsymmetry(const HairBxDF& b) {
  double worst = 0;
  for (double to : {-0.9, -0.2, 0.4})
    for (double ti : {-0.6, 0.1, 0.7})
      for (double phi : {-2.0, 0.5, 2.9}) {
        Vector3f wo = fibreDirection(to, 0.4), wi = fibreDirection(ti, 0.4 + phi);
        worst = std::max(worst, relativeDifference(scattering(b, wo, wi), scattering(b, wi, wo)));
      }
  return worst;
}

TEST(HairBxDF, NotReciprocalOffCentreOrWithTilt) {
  // The model is not reciprocal in general (pbrt 4e §9.9.6): the attenuation follows wo's
  // refracted path and the azimuthal lobes are centred by wo's offset; the tilt rotates theta_i
  // only. Each effect alone makes S(wo, wi) and S(wi, wo) differ by far more than rounding.
  Spectrum sigmaA(0.3f);
  EXPECT_GT(largestAsymmetry(HairBxDF(0.6f, 1.55f, sigmaA, 0.3f, 0.3f, 0)), 0.1);
  EXPECT_GT(largestAsymmetry(HairBxDF(0, 1.55f, sigmaA, 0.3f, 0.3f, 2)), 0.1);
  EXPECT_GT(largestAsymmetry(HairBxDF(0, 1.55f, sigmaA, 0.3f, 0.3f, 0)), 0.1);
}

TEST(HairBxDF, ColourInversionDarkensMonotonically) {
  // The fibre's albedo integral of S over the sphere, averaged over h and wo, for sigma_a from
  // colours 0.1 .. 1. The same random numbers for every colour (common random numbers), so the
  // estimates inherit S's pointwise monotonicity in the transmittance: strictly increasing in
  // colour, 1 for white (no absorption, alpha = 0) within the estimate's error.
  constexpr int kSamples = 40000;
  RNG rng(7);
  struct Draw {
    Float h;
    Vector3f wo, wi;
  };
  std::vector<Draw> draws(kSamples);
  for (Draw& d : draws) {
    d.h = -1 + 2 * rng.uniformFloat();
    d.wo = sampleUniformSphere({rng.uniformFloat(), rng.uniformFloat()});
    d.wi = sampleUniformSphere({rng.uniformFloat(), rng.uniformFloat()});
  }
  double previous = 0, standardError = 0;
  for (Float c = 0.1f; c < 1.05f; c += 0.1f) {
    Float betaN = 0.3f;
    Spectrum sigmaA = hair::sigmaAFromReflectance(Spectrum(std::min(c, Float(1))), betaN);
    double sum = 0, sum2 = 0;
    for (const Draw& d : draws) {
      double x = scattering(HairBxDF(d.h, 1.55f, sigmaA, 0.3f, betaN, 0), d.wo, d.wi)[0] /
                 uniformSpherePdf();
      sum += x;
      sum2 += x * x;
    }
    double albedo = sum / kSamples;
    standardError = std::sqrt((sum2 / kSamples - albedo * albedo) / (kSamples - 1));
    EXPECT_GT(albedo, previous) << "colour " << c;
    previous = albedo;
  }
  // White: 1 up to the uniform estimate's error; 4 standard errors is a two-sided significance of
  // 6e-5.
  EXPECT_NEAR(previous, 1, 4 * standardError);
}

}  // namespace
}  // namespace candela
