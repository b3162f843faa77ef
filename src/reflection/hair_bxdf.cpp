#include "reflection/hair_bxdf.h"

#include <cmath>

#include "core/rng.h"

namespace candela {

using hair::kMaxLobe;

namespace {

// sin and cos of theta, from w's components along and across the fibre normalised together in
// double: 1 - sin^2 loses every digit within 2e-4 of the fibre's axis (where a tilted lobe's
// density per solid angle grows like 1 / cos theta), and a Float w is unit only to 1e-7, which
// narrow lobes (v ~ 1e-3) would magnify a hundredfold if sin and cos disagreed.
struct FibreAngle {
  double sin, cos;
};
FibreAngle fibreAngle(const Vector3f& w) {
  double across = std::sqrt(double(w.y) * w.y + double(w.z) * w.z);
  double length = std::sqrt(double(w.x) * w.x + across * across);
  if (length == 0) return {0, 1};
  return {w.x / length, across / length};
}

}  // namespace

struct HairBxDF::Outgoing {
  double sinTheta, cosTheta;
  Float phi, gammaT;
  hair::LobeSpectra ap;
};

HairBxDF::HairBxDF(Float h, Float eta, const Spectrum& sigmaA, Float betaM, Float betaN,
                   Float alphaDegrees)
    : BxDF(BxDFType(kReflection | kTransmission | kGlossy)),
      h_(clamp(h, -1, 1)),
      gammaO_(safeAsin(h)),
      eta_(eta),
      sigmaA_(sigmaA),
      s_(hair::azimuthalScale(betaN)) {
  // TT is the narrowest lobe, TRT and longer paths the widest (Chiang et al. §4.1).
  double v = hair::longitudinalVariance(betaM);
  v_[0] = v;
  v_[1] = v / 4;
  v_[2] = v_[3] = 4 * v;
  const double tilt[kMaxLobe] = {-2, 1, 4};
  double alpha = double(alphaDegrees) * M_PI / 180;
  for (int p = 0; p < kMaxLobe; ++p) {
    sinTilt_[p] = std::sin(tilt[p] * alpha);
    cosTilt_[p] = std::cos(tilt[p] * alpha);
  }
}

HairBxDF::Outgoing HairBxDF::outgoing(const Vector3f& wo) const {
  Outgoing o;
  FibreAngle a = fibreAngle(wo);
  o.sinTheta = a.sin;
  o.cosTheta = a.cos;
  o.phi = std::atan2(wo.z, wo.y);
  // Inside, the longitudinal angle refracts by Snell's law, and the projection onto the normal
  // plane refracts with Bravais' index eta' = sqrt(eta^2 - sin^2 theta_o) / cos theta_o
  // (pbrt 4e §9.9.4).
  double sinThetaT = o.sinTheta / eta_;
  double cosThetaT = std::sqrt(std::max(0.0, 1 - sinThetaT * sinThetaT));
  double etap = std::sqrt(std::max(0.0, double(eta_) * eta_ - o.sinTheta * o.sinTheta)) /
                std::max(o.cosTheta, 1e-12);
  double sinGammaT = std::clamp(h_ / etap, -1.0, 1.0);
  double cosGammaT = std::sqrt(std::max(0.0, 1 - sinGammaT * sinGammaT));
  o.gammaT = Float(std::asin(sinGammaT));
  // The chord through the unit circle at gamma_t, lengthened by the longitudinal slope.
  double length = 2 * cosGammaT / std::max(cosThetaT, 1e-12);
  Spectrum t;
  for (int i = 0; i < 3; ++i)
    t[i] = sigmaA_[i] == 0 || length == 0 ? 1 : Float(std::exp(-double(sigmaA_[i]) * length));
  o.ap = hair::attenuation(Float(o.cosTheta), eta_, h_, t);
  return o;
}

Spectrum HairBxDF::lobeSum(const Outgoing& o, const Vector3f& wi) const {
  auto [sinI, cosI] = fibreAngle(wi);
  Float phi = std::atan2(wi.z, wi.y) - o.phi;
  Spectrum sum(0);
  for (int p = 0; p < kMaxLobe; ++p) {
    // theta_i rotated by the lobe's tilt; past a pole the cosine turns negative, which Mp (through
    // I0, an even function) does not see.
    double sinIp = sinI * cosTilt_[p] + cosI * sinTilt_[p];
    double cosIp = std::abs(cosI * cosTilt_[p] - sinI * sinTilt_[p]);
    double mp = hair::longitudinalScattering(cosIp, o.cosTheta, sinIp, o.sinTheta, v_[p]);
    sum += o.ap[p] * Float(mp * hair::azimuthalScattering(phi, p, s_, gammaO_, o.gammaT));
  }
  double mp = hair::longitudinalScattering(cosI, o.cosTheta, sinI, o.sinTheta, v_[kMaxLobe]);
  return sum + o.ap[kMaxLobe] * Float(mp * kInv2Pi);
}

Float HairBxDF::density(const Outgoing& o, const Vector3f& wi, const hair::LobeWeights& w) const {
  auto [sinI, cosI] = fibreAngle(wi);
  if (cosI == 0) return 0;
  Float phi = std::atan2(wi.z, wi.y) - o.phi;
  double sum = 0;
  for (int p = 0; p < kMaxLobe; ++p) {
    if (w[p] == 0) continue;
    // sampleF draws theta from Mp cos(theta) and turns it to theta_i = theta - tilt: per solid
    // angle that is Mp(theta) cos(theta) / cos(theta_i). A theta_i is reached from theta_i + tilt
    // directly when that lies within [-pi/2, pi/2], and from across the pole (azimuth turned by
    // pi, sin theta = sin(theta_i - tilt)) when theta_i - tilt lies beyond it.
    double q = 0;
    double cosDirect = cosI * cosTilt_[p] - sinI * sinTilt_[p];
    if (cosDirect >= 0) {
      double sinDirect = sinI * cosTilt_[p] + cosI * sinTilt_[p];
      q += hair::longitudinalScattering(cosDirect, o.cosTheta, sinDirect, o.sinTheta, v_[p]) *
           cosDirect * hair::azimuthalScattering(phi, p, s_, gammaO_, o.gammaT);
    }
    double cosAcross = -(cosI * cosTilt_[p] + sinI * sinTilt_[p]);
    if (cosAcross > 0) {
      double sinAcross = sinI * cosTilt_[p] - cosI * sinTilt_[p];
      q += hair::longitudinalScattering(cosAcross, o.cosTheta, sinAcross, o.sinTheta, v_[p]) *
           cosAcross * hair::azimuthalScattering(phi + kPi, p, s_, gammaO_, o.gammaT);
    }
    sum += w[p] * q / cosI;
  }
  double mp = hair::longitudinalScattering(cosI, o.cosTheta, sinI, o.sinTheta, v_[kMaxLobe]);
  return Float(sum + w[kMaxLobe] * mp * kInv2Pi);
}

Spectrum HairBxDF::f(const Vector3f& wo, const Vector3f& wi) const {
  Float c = absCosTheta(wi);
  if (c == 0) return Spectrum(0);
  return lobeSum(outgoing(wo), wi) / c;
}

hair::LobeSpectra HairBxDF::attenuation(const Vector3f& wo) const { return outgoing(wo).ap; }

namespace {

hair::LobeWeights probabilities(const hair::LobeSpectra& ap) {
  hair::LobeWeights w{};
  Float sum = 0;
  for (int p = 0; p <= kMaxLobe; ++p) sum += w[p] = std::max(Float(0), ap[p].y());
  if (sum > 0)
    for (Float& x : w) x /= sum;
  return w;
}

}  // namespace

hair::LobeWeights HairBxDF::lobeProbabilities(const Vector3f& wo) const {
  return probabilities(outgoing(wo).ap);
}

Float HairBxDF::pdf(const Vector3f& wo, const Vector3f& wi) const {
  Outgoing o = outgoing(wo);
  return density(o, wi, probabilities(o.ap));
}

Spectrum HairBxDF::sampleF(const Vector3f& wo, Vector3f* wi, const Point2f& u, Float* pdf,
                           BxDFType* sampledType) const {
  *pdf = 0;
  Outgoing o = outgoing(wo);
  hair::LobeWeights w = probabilities(o.ap);
  int p = 0;
  Float r = u.x;
  while (p < kMaxLobe && (w[p] == 0 || r >= w[p])) r -= w[p++];
  if (w[p] == 0) return Spectrum(0);
  // The remainder is uniform again: it samples Np. Mp's rotation about the cone, the least
  // sensitive of the four numbers, is hashed from both inputs: splitting digits off one of them
  // would leave it a few hundred distinct values for the rarely picked lobes.
  r = std::clamp(r / w[p], Float(0), kOneMinusEpsilon);
  uint64_t bits = (uint64_t(floatToBits(u.x)) << 32) | floatToBits(u.y);
  Float coneU = Float(mixBits(bits) >> 40) * 0x1p-24f;
  double sinI, cosI;
  hair::sampleLongitudinal(o.sinTheta, o.cosTheta, v_[p], u.y, coneU, &sinI, &cosI);
  Float dphi = 2 * kPi * r;
  if (p < kMaxLobe) {
    // Mp was sampled around the untilted cone; evaluation tilts theta_i by the lobe's angle.
    double s = sinI * cosTilt_[p] - cosI * sinTilt_[p];
    double c = cosI * cosTilt_[p] + sinI * sinTilt_[p];
    sinI = s;
    cosI = c;
    dphi =
        hair::azimuthalShift(p, gammaO_, o.gammaT) + hair::sampleTrimmedLogistic(r, s_, -kPi, kPi);
  }
  double phiI = double(o.phi) + dphi;
  *wi = Vector3f(Float(sinI), Float(cosI * std::cos(phiI)), Float(cosI * std::sin(phiI)));
  *pdf = density(o, *wi, w);
  if (sampledType) *sampledType = type();
  Float c = absCosTheta(*wi);
  if (*pdf == 0 || c == 0) {
    *pdf = 0;
    return Spectrum(0);
  }
  return lobeSum(o, *wi) / c;
}

}  // namespace candela
