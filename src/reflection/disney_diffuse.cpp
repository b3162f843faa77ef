#include "reflection/disney_diffuse.h"

namespace candela {

Float cosThetaD(const Vector3f& wo, const Vector3f& wi) {
  Vector3f wh = wo + wi;
  if (wh.lengthSquared() == 0) return 1;
  // Both directions make the same angle with wh; their mean keeps f exactly reciprocal.
  wh = normalize(wh);
  return clamp(Float(0.5) * (dot(wi, wh) + dot(wo, wh)), 0, 1);
}

Spectrum DisneyDiffuse::f(const Vector3f& wo, const Vector3f& wi) const {
  Float fo = schlickWeight(absCosTheta(wo)), fi = schlickWeight(absCosTheta(wi));
  return c_ * (kInvPi * (1 - fo / 2) * (1 - fi / 2));
}

Spectrum DisneyRetroReflection::f(const Vector3f& wo, const Vector3f& wi) const {
  Float cd = cosThetaD(wo, wi);
  Float rr = 2 * roughness_ * cd * cd;
  Float fo = schlickWeight(absCosTheta(wo)), fi = schlickWeight(absCosTheta(wi));
  return c_ * (kInvPi * rr * (fo + fi + fo * fi * (rr - 1)));
}

Spectrum DisneyFakeSubsurface::f(const Vector3f& wo, const Vector3f& wi) const {
  Float co = absCosTheta(wo), ci = absCosTheta(wi);
  if (co == 0 || ci == 0) return Spectrum(0);
  Float cd = cosThetaD(wo, wi);
  Float fss90 = roughness_ * cd * cd;
  Float fo = schlickWeight(co), fi = schlickWeight(ci);
  Float fss = (1 + (fss90 - 1) * fo) * (1 + (fss90 - 1) * fi);
  return c_ * (kInvPi * Float(1.25) * (fss * (1 / (co + ci) - Float(0.5)) + Float(0.5)));
}

Spectrum DisneySheen::f(const Vector3f& wo, const Vector3f& wi) const {
  return c_ * schlickWeight(cosThetaD(wo, wi));
}

}  // namespace candela
