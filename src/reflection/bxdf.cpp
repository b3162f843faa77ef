#include "reflection/bxdf.h"

#include "core/sampling.h"

namespace candela {

Spectrum BxDF::sampleF(const Vector3f& wo, Vector3f* wi, const Point2f& u, Float* pdfOut,
                       BxDFType* sampledType) const {
  *wi = sampleCosineHemisphere(u);
  if (wo.z < 0) wi->z = -wi->z;
  *pdfOut = pdf(wo, *wi);
  if (sampledType) *sampledType = type_;
  return f(wo, *wi);
}

Float BxDF::pdf(const Vector3f& wo, const Vector3f& wi) const {
  return sameHemisphere(wo, wi) ? absCosTheta(wi) * kInvPi : 0;
}

namespace {
// Sums in double: thousands of float additions would lose ~1e-4 of the result.
struct SpectrumSum {
  double v[3] = {0, 0, 0};
  void add(const Spectrum& s) {
    for (int c = 0; c < 3; ++c) v[c] += s[c];
  }
  Spectrum mean(double scale) const {
    return {Float(v[0] * scale), Float(v[1] * scale), Float(v[2] * scale)};
  }
};

// rho_hd over sampleF's samples; side 0 counts every sample, +1 only reflected ones (wi on wo's
// side), -1 only transmitted ones.
Spectrum directionalAlbedo(const BxDF& b, const Vector3f& wo, std::span<const Point2f> u,
                           int side) {
  SpectrumSum sum;
  for (const Point2f& s : u) {
    Vector3f wi;
    Float p = 0;
    Spectrum f = b.sampleF(wo, &wi, s, &p);
    if (p > 0 && (side == 0 || sameHemisphere(wo, wi) == (side > 0)))
      sum.add(f * (absCosTheta(wi) / p));
  }
  return sum.mean(u.empty() ? 0 : 1.0 / double(u.size()));
}

Spectrum hemisphericalAlbedo(const BxDF& b, std::span<const Point2f> u1,
                             std::span<const Point2f> u2, int side) {
  // rho_hh = (1/pi) integral integral f |cos theta_o| |cos theta_i| dwo dwi.
  SpectrumSum sum;
  size_t n = std::min(u1.size(), u2.size());
  for (size_t i = 0; i < n; ++i) {
    Vector3f wo = sampleUniformHemisphere(u1[i]), wi;
    Float pdfO = uniformHemispherePdf(), pdfI = 0;
    Spectrum f = b.sampleF(wo, &wi, u2[i], &pdfI);
    if (pdfI > 0 && (side == 0 || sameHemisphere(wo, wi) == (side > 0)))
      sum.add(f * (absCosTheta(wi) * absCosTheta(wo) / (pdfO * pdfI)));
  }
  return sum.mean(n == 0 ? 0 : 1.0 / (M_PI * double(n)));
}

}  // namespace

Spectrum BxDF::rho(const Vector3f& wo, std::span<const Point2f> u) const {
  return directionalAlbedo(*this, wo, u, 0);
}

Spectrum BxDF::rho(std::span<const Point2f> u1, std::span<const Point2f> u2) const {
  return hemisphericalAlbedo(*this, u1, u2, 0);
}

Spectrum BxDF::rhoOneSide(const Vector3f& wo, std::span<const Point2f> u, bool reflection) const {
  return directionalAlbedo(*this, wo, u, reflection ? 1 : -1);
}

Spectrum BxDF::rhoOneSide(std::span<const Point2f> u1, std::span<const Point2f> u2,
                          bool reflection) const {
  return hemisphericalAlbedo(*this, u1, u2, reflection ? 1 : -1);
}

std::vector<Point2f> stratifiedSamples2D(int n, RNG& rng) {
  std::vector<Point2f> s;
  s.reserve(size_t(n) * size_t(n));
  Float inv = Float(1) / Float(n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x)
      s.emplace_back(std::min((x + rng.uniformFloat()) * inv, kOneMinusEpsilon),
                     std::min((y + rng.uniformFloat()) * inv, kOneMinusEpsilon));
  // Shuffle so that pairing two such sets does not correlate their strata.
  for (size_t i = s.size(); i > 1; --i) std::swap(s[i - 1], s[rng.uniformUInt32(uint32_t(i))]);
  return s;
}

Spectrum rhoStratified(const BxDF& bxdf, const Vector3f& wo, int sqrtSamples, RNG& rng) {
  std::vector<Point2f> u = stratifiedSamples2D(sqrtSamples, rng);
  return bxdf.rho(wo, u);
}

Spectrum rhoStratified(const BxDF& bxdf, int sqrtSamples, RNG& rng) {
  std::vector<Point2f> u1 = stratifiedSamples2D(sqrtSamples, rng);
  std::vector<Point2f> u2 = stratifiedSamples2D(sqrtSamples, rng);
  return bxdf.rho(u1, u2);
}

}  // namespace candela
