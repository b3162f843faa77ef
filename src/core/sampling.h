// Monte Carlo sampling routines (lrt draft §14-15; Shirley, Realistic Ray Tracing ch. 3). Every
// sampleX has a matching pdf; the statistical tests check each pair.
#pragma once

#include <vector>

#include "core/vector.h"

namespace candela {

// sin x and cos x for |x| <= pi/4 by their Taylor series to x^9 and x^10: the next terms are
// below 2e-9, under a Float ulp, and no range reduction is needed (what libm's sincosf spends
// most of its time on).
inline void sinCosQuarterPi(Float x, Float* sinX, Float* cosX) {
  Float x2 = x * x;
  *sinX =
      x * (1 + x2 * (Float(-1.0 / 6) + x2 * (Float(1.0 / 120) + x2 * (Float(-1.0 / 5040) +
                                                                      x2 * Float(1.0 / 362880)))));
  *cosX =
      1 + x2 * (Float(-0.5) + x2 * (Float(1.0 / 24) +
                                    x2 * (Float(-1.0 / 720) +
                                          x2 * (Float(1.0 / 40320) + x2 * Float(-1.0 / 3628800)))));
}

// Shirley and Chiu's map: the square's concentric squares to circles, the angle within each
// octant linear in the offset along the square's side, so it stays within +-pi/4 of an axis.
// Inline with the next: one per path vertex, where a call costs a tenth of the work.
inline Point2f sampleUniformDiskConcentric(const Point2f& u) {
  Point2f o(2 * u.x - 1, 2 * u.y - 1);
  if (o.x == 0 && o.y == 0) return Point2f(0, 0);
  Float s, c;
  if (std::abs(o.x) > std::abs(o.y)) {
    sinCosQuarterPi(kPiOver4 * (o.y / o.x), &s, &c);
    return Point2f(o.x * c, o.x * s);
  }
  // theta = pi/2 - x: cos theta = sin x, sin theta = cos x.
  sinCosQuarterPi(kPiOver4 * (o.x / o.y), &s, &c);
  return Point2f(o.y * s, o.y * c);
}
Point2f sampleUniformDiskPolar(const Point2f& u);
Vector3f sampleUniformHemisphere(const Point2f& u);
inline Float uniformHemispherePdf() { return kInv2Pi; }
Vector3f sampleUniformSphere(const Point2f& u);
inline Float uniformSpherePdf() { return kInv4Pi; }
// Malley's method: concentric disk samples projected up to the hemisphere.
inline Vector3f sampleCosineHemisphere(const Point2f& u) {
  Point2f d = sampleUniformDiskConcentric(u);
  Float z = safeSqrt(1 - d.x * d.x - d.y * d.y);
  return Vector3f(d.x, d.y, z);
}
inline Float cosineHemispherePdf(Float cosTheta) { return cosTheta * kInvPi; }
// Directions within cosThetaMax of +z, uniform in solid angle.
Vector3f sampleUniformCone(const Point2f& u, Float cosThetaMax);
inline Float uniformConePdf(Float cosThetaMax) { return 1 / (2 * kPi * (1 - cosThetaMax)); }
// Barycentrics (b0, b1) uniform over a triangle. Inline: every triangle light sample takes one.
inline Point2f sampleUniformTriangle(const Point2f& u) {
  Float su0 = std::sqrt(u.x);
  return Point2f(1 - su0, u.y * su0);
}

inline Float balanceHeuristic(int nf, Float fPdf, int ng, Float gPdf) {
  return (nf * fPdf) / (nf * fPdf + ng * gPdf);
}
// Veach's power heuristic with beta = 2.
inline Float powerHeuristic(int nf, Float fPdf, int ng, Float gPdf) {
  Float f = nf * fPdf, g = ng * gPdf;
  if (std::isinf(f * f)) return 1;
  if (f == 0 && g == 0) return 0;
  return (f * f) / (f * f + g * g);
}

// Piecewise-constant 1D distribution over [0, 1) proportional to func.
class Distribution1D {
 public:
  explicit Distribution1D(std::vector<Float> func);
  int count() const { return int(func_.size()); }
  Float integral() const { return funcInt_; }
  // Continuous sample in [0, 1); *pdf is the density there, *offset the segment.
  Float sampleContinuous(Float u, Float* pdf, int* offset = nullptr) const;
  int sampleDiscrete(Float u, Float* pmf = nullptr) const;
  Float discretePmf(int i) const { return funcInt_ > 0 ? func_[i] / (funcInt_ * count()) : 0; }
  Float func(int i) const { return func_[i]; }

 private:
  std::vector<Float> func_, cdf_;
  Float funcInt_ = 0;
};

// Piecewise-constant 2D distribution on [0,1)^2 from a nu x nv grid (row v-major).
class Distribution2D {
 public:
  Distribution2D(const std::vector<Float>& func, int nu, int nv);
  Point2f sampleContinuous(const Point2f& u, Float* pdf) const;
  Float pdf(const Point2f& p) const;

 private:
  std::vector<Distribution1D> conditional_;
  Distribution1D marginal_;
};

}  // namespace candela
