#include "reflection/dipole.h"

#include <algorithm>
#include <cmath>

namespace candela {

Float diffuseFresnelReflectance(Float eta) {
  return -1.440f / (eta * eta) + 0.710f / eta + 0.668f + 0.0636f * eta;
}

Float dipoleBoundaryA(Float eta) {
  Float fdr = diffuseFresnelReflectance(eta);
  return (1 + fdr) / (1 - fdr);
}

Float totalDiffuseReflectance(Float reducedAlbedo, Float A) {
  Float s = std::sqrt(3 * std::max(Float(0), 1 - reducedAlbedo));
  return reducedAlbedo / 2 * (1 + std::exp(-Float(4) / 3 * A * s)) * std::exp(-s);
}

Float totalDiffuseReflectanceOfAbsorption(Float absorbedFraction, Float A) {
  Float s = std::sqrt(3 * std::max(Float(0), absorbedFraction));
  return (1 - absorbedFraction) / 2 * (1 + std::exp(-Float(4) / 3 * A * s)) * std::exp(-s);
}

Float absorbedFractionForDiffuseReflectance(Float rd, Float A) {
  rd = std::clamp(rd, Float(0), Float(1));
  // Bisection in double: 42 halvings of [0, 1] leave an interval below 1e-12.
  double lo = 0, hi = 1;
  for (int i = 0; i < 42; ++i) {
    double mid = (lo + hi) / 2;
    double s = std::sqrt(3 * mid);
    double value = (1 - mid) / 2 * (1 + std::exp(-4.0 / 3 * A * s)) * std::exp(-s);
    (value > rd ? lo : hi) = mid;
  }
  return Float((lo + hi) / 2);
}

BSSRDFCoefficients coefficientsFromDiffuse(const Spectrum& kd, Float meanFreePath, Float eta) {
  Float A = dipoleBoundaryA(eta);
  BSSRDFCoefficients c;
  c.eta = eta;
  for (int i = 0; i < 3; ++i) {
    // sigma_t' = 1 / mfp split by the reduced albedo (pbrt 2e §16.5).
    Float absorbed = absorbedFractionForDiffuseReflectance(kd[i], A);
    c.sigmaPrimeS[i] = (1 - absorbed) / meanFreePath;
    c.sigmaA[i] = absorbed / meanFreePath;
  }
  return c;
}

DipoleProfile::DipoleProfile(const BSSRDFCoefficients& c)
    : A_(dipoleBoundaryA(c.eta)), eta_(c.eta) {
  for (int i = 0; i < 3; ++i) {
    Float sigmaA = std::max(Float(0), c.sigmaA[i]);
    Float sigmaPrimeT = sigmaA + std::max(Float(0), c.sigmaPrimeS[i]);
    if (sigmaPrimeT <= 0) {
      // No medium in this channel: nothing is scattered back.
      albedo_[i] = 0;
      absorbed_[i] = 1;
      sigmaTr_[i] = 0;
      zr_[i] = zv_[i] = 1;
      continue;
    }
    albedo_[i] = std::max(Float(0), c.sigmaPrimeS[i]) / sigmaPrimeT;
    absorbed_[i] = sigmaA / sigmaPrimeT;
    sigmaTr_[i] = std::sqrt(3 * sigmaA * sigmaPrimeT);
    zr_[i] = 1 / sigmaPrimeT;
    zv_[i] = zr_[i] * (1 + Float(4) / 3 * A_);
  }
}

Spectrum DipoleProfile::Rd(Float r2) const {
  constexpr Float kInv4Pi = Float(1 / (4 * 3.14159265358979323846));
  Spectrum rd(0);
  for (int i = 0; i < 3; ++i) {
    if (albedo_[i] == 0) continue;
    Float dr = std::sqrt(r2 + zr_[i] * zr_[i]);
    Float dv = std::sqrt(r2 + zv_[i] * zv_[i]);
    Float real = zr_[i] * (sigmaTr_[i] * dr + 1) * std::exp(-sigmaTr_[i] * dr) / (dr * dr * dr);
    Float virt = zv_[i] * (sigmaTr_[i] * dv + 1) * std::exp(-sigmaTr_[i] * dv) / (dv * dv * dv);
    rd[i] = albedo_[i] * kInv4Pi * (real + virt);
  }
  return rd;
}

Spectrum DipoleProfile::totalReflectance() const {
  Spectrum t(0);
  for (int i = 0; i < 3; ++i) t[i] = totalDiffuseReflectanceOfAbsorption(absorbed_[i], A_);
  return t;
}

}  // namespace candela
