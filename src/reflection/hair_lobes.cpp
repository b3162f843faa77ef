#include "reflection/hair_lobes.h"

#include <cmath>

#include "reflection/fresnel.h"

namespace candela::hair {

double longitudinalVariance(Float betaM) {
  double b = betaM;
  double sd = 0.726 * b + 0.812 * b * b + 3.7 * std::pow(b, 20);
  return sd * sd;
}

Float azimuthalScale(Float betaN) {
  double b = betaN;
  return Float(std::sqrt(M_PI / 8) * (0.265 * b + 1.194 * b * b + 5.372 * std::pow(b, 22)));
}

namespace {

// Below this the power series, from it on the asymptotic expansion.
constexpr double kAsymptoticFrom = 30;

// I0(x) = sum_k (x^2 / 4)^k / (k!)^2 (Abramowitz & Stegun 9.6.12): positive terms, so no
// cancellation; about 70 terms at x = 30. Our own rather than std::cyl_bessel_i, whose libstdc++
// implementation calls lgamma, which writes the global signgam: a data race between render
// threads (ThreadSanitizer found it).
double besselI0Series(double x) {
  const double t = x * x / 4;
  double term = 1, sum = 1;
  for (int k = 1; term > 1e-17 * sum; ++k) {
    term *= t / (double(k) * k);
    sum += term;
  }
  return sum;
}

// I0(x) sqrt(2 pi x) / e^x ~ sum_k ((2k-1)!!)^2 / (k! (8x)^k) (Abramowitz & Stegun 9.7.1): from
// x = 30 the 17th term is below 4e-18, and the terms still fall there.
double besselI0AsymptoticSum(double x) {
  double term = 1, sum = 1;
  for (int k = 1; k <= 16; ++k) {
    term *= double(2 * k - 1) * (2 * k - 1) / (8.0 * k * x);
    sum += term;
  }
  return sum;
}

}  // namespace

double besselI0(double x) {
  x = std::abs(x);
  if (x < kAsymptoticFrom) return besselI0Series(x);
  return std::exp(x) / std::sqrt(2 * M_PI * x) * besselI0AsymptoticSum(x);
}

double logBesselI0(double x) {
  x = std::abs(x);
  // Finite where I0 itself overflows (x > 713).
  if (x < kAsymptoticFrom) return std::log(besselI0Series(x));
  return x - 0.5 * std::log(2 * M_PI * x) + std::log(besselI0AsymptoticSum(x));
}

double longitudinalScattering(double cosThetaI, double cosThetaO, double sinThetaI,
                              double sinThetaO, double v) {
  double a = cosThetaI * cosThetaO / v, b = sinThetaI * sinThetaO / v;
  if (v > 0.1) return std::exp(-b) * besselI0(a) / (2 * v * std::sinh(1 / v));
  // log(2 v sinh(1/v)) = log v + 1/v + log(1 - e^(-2/v)): I0(a) and sinh(1/v) overflow apart
  // while their ratio stays finite.
  double logNorm = std::log(v) + 1 / v + std::log1p(-std::exp(-2 / v));
  return std::exp(logBesselI0(a) - b - logNorm);
}

void sampleLongitudinal(double sinThetaO, double cosThetaO, double v, Float u1, Float u2,
                        double* sinThetaI, double* cosThetaI) {
  double u = std::max(double(u1), 1e-5);
  // cos of the angle to the cone's axis direction: the inverse CDF of e^(cos / v).
  double cosT = 1 + v * std::log(u + (1 - u) * std::exp(-2 / v));
  double sinT = std::sqrt(std::max(0.0, 1 - cosT * cosT));
  double cosPhi = std::cos(2 * M_PI * double(u2));
  double s = -cosT * sinThetaO + sinT * cosPhi * cosThetaO;
  *sinThetaI = std::clamp(s, -1.0, 1.0);
  *cosThetaI = std::sqrt(std::max(0.0, 1 - *sinThetaI * *sinThetaI));
}

Float logistic(Float x, Float s) {
  double e = std::exp(-std::abs(double(x)) / s);
  return Float(e / (s * (1 + e) * (1 + e)));
}

Float logisticCDF(Float x, Float s) { return Float(1 / (1 + std::exp(-double(x) / s))); }

Float trimmedLogistic(Float x, Float s, Float a, Float b) {
  return logistic(x, s) / (logisticCDF(b, s) - logisticCDF(a, s));
}

Float sampleTrimmedLogistic(Float u, Float s, Float a, Float b) {
  double ca = logisticCDF(a, s), k = double(logisticCDF(b, s)) - ca;
  double x = -double(s) * std::log(1 / (double(u) * k + ca) - 1);
  return Float(std::clamp(x, double(a), double(b)));
}

Float azimuthalShift(int p, Float gammaO, Float gammaT) {
  return 2 * Float(p) * gammaT - 2 * gammaO + Float(p) * kPi;
}

Float azimuthalScattering(Float phi, int p, Float s, Float gammaO, Float gammaT) {
  double d = std::remainder(double(phi) - azimuthalShift(p, gammaO, gammaT), 2 * M_PI);
  return trimmedLogistic(Float(d), s, -kPi, kPi);
}

LobeSpectra attenuation(Float cosThetaO, Float eta, Float h, const Spectrum& transmittance) {
  Float cosGammaO = safeSqrt(1 - h * h);
  Float f = fresnelDielectric(cosThetaO * cosGammaO, 1, eta);
  const Spectrum& t = transmittance;
  LobeSpectra a;
  a[0] = Spectrum(f);
  a[1] = t * ((1 - f) * (1 - f));
  for (int p = 2; p < kMaxLobe; ++p) a[p] = a[p - 1] * t * f;
  // Spectrum division is 0 where the divisor is: then f = T = 1 and (1 - f)^2 = 0 already.
  a[kMaxLobe] = a[kMaxLobe - 1] * t * f / (Spectrum(1) - t * f);
  return a;
}

}  // namespace candela::hair
