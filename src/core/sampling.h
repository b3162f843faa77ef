// Monte Carlo sampling routines (lrt draft §14-15; Shirley, Realistic Ray Tracing ch. 3). Every
// sampleX has a matching pdf; the statistical tests check each pair.
#pragma once

#include <vector>

#include "core/vector.h"

namespace candela {

Point2f sampleUniformDiskConcentric(const Point2f& u);  // Shirley-Chiu mapping
Point2f sampleUniformDiskPolar(const Point2f& u);
Vector3f sampleUniformHemisphere(const Point2f& u);
inline Float uniformHemispherePdf() { return kInv2Pi; }
Vector3f sampleUniformSphere(const Point2f& u);
inline Float uniformSpherePdf() { return kInv4Pi; }
// Malley's method: concentric disk samples projected up to the hemisphere.
Vector3f sampleCosineHemisphere(const Point2f& u);
inline Float cosineHemispherePdf(Float cosTheta) { return cosTheta * kInvPi; }
// Directions within cosThetaMax of +z, uniform in solid angle.
Vector3f sampleUniformCone(const Point2f& u, Float cosThetaMax);
inline Float uniformConePdf(Float cosThetaMax) { return 1 / (2 * kPi * (1 - cosThetaMax)); }
// Barycentrics (b0, b1) uniform over a triangle.
Point2f sampleUniformTriangle(const Point2f& u);

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
