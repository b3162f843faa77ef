#include "reflection/fresnel.h"

namespace candela {

Float frDielectric(Float cosI, Float cosT, Float etaI, Float etaT) {
  Float par = (etaT * cosI - etaI * cosT) / (etaT * cosI + etaI * cosT);
  Float perp = (etaI * cosI - etaT * cosT) / (etaI * cosI + etaT * cosT);
  return (par * par + perp * perp) / 2;
}

Float fresnelDielectric(Float cosThetaI, Float etaOutside, Float etaInside) {
  Float cosI = clamp(cosThetaI, -1, 1);
  Float etaI = etaOutside, etaT = etaInside;
  if (cosI < 0) {  // arriving from inside: the roles of the indices swap (lrt draft §9.2)
    std::swap(etaI, etaT);
    cosI = -cosI;
  }
  // Snell's law; sin theta_t >= 1 is total internal reflection. SpecularTransmission decides
  // with the same arithmetic, so that the two agree exactly at the critical angle.
  Float eta = etaI / etaT;
  Float sin2T = eta * eta * std::max(Float(0), 1 - cosI * cosI);
  if (sin2T >= 1) return 1;
  Float cosT = std::sqrt(1 - sin2T);
  return frDielectric(cosI, cosT, etaI, etaT);
}

Spectrum frConductor(Float cosI, const Spectrum& eta, const Spectrum& k) {
  Spectrum r;
  Float c2 = cosI * cosI;
  for (int i = 0; i < 3; ++i) {
    Float ek = eta[i] * eta[i] + k[i] * k[i];
    Float twoEtaCos = 2 * eta[i] * cosI;
    Float par2 = (ek * c2 - twoEtaCos + 1) / (ek * c2 + twoEtaCos + 1);
    Float perp2 = (ek - twoEtaCos + c2) / (ek + twoEtaCos + c2);
    r[i] = (par2 + perp2) / 2;
  }
  return r;
}

Spectrum fresnelApproxEta(const Spectrum& r) {
  Spectrum e;
  for (int i = 0; i < 3; ++i) {
    Float s = std::sqrt(clamp(r[i], 0, 0.999f));
    e[i] = (1 + s) / (1 - s);
  }
  return e;
}

Spectrum fresnelApproxK(const Spectrum& r) {
  Spectrum k;
  for (int i = 0; i < 3; ++i) {
    Float c = clamp(r[i], 0, 0.999f);
    k[i] = 2 * std::sqrt(c / (1 - c));
  }
  return k;
}

}  // namespace candela
