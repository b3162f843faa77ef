#include "reflection/oren_nayar.h"

namespace candela {

OrenNayar::OrenNayar(const Spectrum& r, Float sigmaDeg)
    : BxDF(BxDFType(kReflection | kDiffuse)), r_(r) {
  Float sigma = radians(sigmaDeg);
  Float s2 = sigma * sigma;
  a_ = 1 - s2 / (2 * (s2 + 0.33f));
  b_ = 0.45f * s2 / (s2 + 0.09f);
}

Spectrum OrenNayar::f(const Vector3f& wo, const Vector3f& wi) const {
  Float sinThetaI = safeSqrt(1 - wi.z * wi.z), sinThetaO = safeSqrt(1 - wo.z * wo.z);
  // cos(phi_i - phi_o) without dividing by sin(theta) at normal incidence.
  Float maxCos = 0;
  if (sinThetaI > 1e-4f && sinThetaO > 1e-4f) {
    Float dCos = (wi.x * wo.x + wi.y * wo.y) / (sinThetaI * sinThetaO);
    maxCos = std::max(Float(0), dCos);
  }
  Float sinAlpha, tanBeta;
  if (std::max(absCosTheta(wi), absCosTheta(wo)) == 0) {
    sinAlpha = tanBeta = 0;  // both at grazing: tan(beta) would be 0 / 0
  } else if (absCosTheta(wi) > absCosTheta(wo)) {
    sinAlpha = sinThetaO;
    tanBeta = sinThetaI / absCosTheta(wi);
  } else {
    sinAlpha = sinThetaI;
    tanBeta = sinThetaO / absCosTheta(wo);
  }
  return r_ * kInvPi * (a_ + b_ * maxCos * sinAlpha * tanBeta);
}

}  // namespace candela
