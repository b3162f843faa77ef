#include "shapes/hyperboloid_profile.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace candela {

HyperboloidFit fitHyperboloid(const double p1[3], const double p2[3]) {
  HyperboloidFit f;
  std::copy(p1, p1 + 3, f.p1);
  std::copy(p2, p2 + 3, f.p2);
  if (f.p2[2] == 0) std::swap(f.p1, f.p2);
  const double* a = f.p1;
  const double* b = f.p2;
  // rho^2 = d + k z^2 through (s, t) = (rho^2, z^2) of b and of q: two linear equations in d, k.
  double s2 = b[0] * b[0] + b[1] * b[1], t2 = b[2] * b[2];
  for (int m = 1; m <= 4; ++m) {
    double q[3];
    for (int i = 0; i < 3; ++i) q[i] = a[i] + 2 * m * (b[i] - a[i]);
    double s1 = q[0] * q[0] + q[1] * q[1], t1 = q[2] * q[2];
    // pbrt's a = (t2 - t1) / det is infinite (or NaN) when det = 0, q and b on one cone through
    // the origin: pbrt then tries the next m. A line meets such a cone twice at most, so two
    // failures in a row mean the line lies on it.
    double det = s1 * t2 - s2 * t1;
    if (std::abs(det) <= 1e-12 * (std::abs(s1 * t2) + std::abs(s2 * t1))) continue;
    if (t1 == t2) {  // a = 0: the planes z = +-|b.z|
      f.degenerate = true;
      return f;
    }
    f.k = (s1 - s2) / (t1 - t2);
    f.d = (s2 * t1 - s1 * t2) / (t1 - t2);
    return f;
  }
  f.k = s2 / t2;  // b.z != 0 after the swap
  f.d = 0;
  return f;
}

HyperboloidProfile::HyperboloidProfile(double k, double d, double zMin, double zMax)
    : k_(k), d_(d), qa_(k * (1 + k)), qd_(d) {
  auto addSpan = [&](double lo, double hi) {
    if (!(hi > lo)) return;
    lo_[nSpans_] = lo;
    hi_[nSpans_] = hi;
    ++nSpans_;
  };
  if (k == 0) {
    if (d > 0) addSpan(zMin, zMax);
  } else if (k > 0) {
    if (d >= 0) {
      addSpan(zMin, zMax);
    } else {  // two sheets, none for |z| < zc
      double zc = std::sqrt(-d / k);
      addSpan(zMin, std::min(zMax, -zc));
      addSpan(std::max(zMin, zc), zMax);
    }
  } else if (d > 0) {  // an ellipsoid: none for |z| > zc
    double zc = std::sqrt(d / -k);
    addSpan(std::max(zMin, -zc), std::min(zMax, zc));
  }
  for (int i = 0; i < nSpans_; ++i) spanArea_[i] = std::max(0.0, strip(hi_[i]) - strip(lo_[i]));
}

double HyperboloidProfile::strip(double z) const {
  // The integrand sqrt(q), q = qa z^2 + qd, is real on the spans (q = rho^2 + (k z)^2 there).
  double s = std::sqrt(std::max(0.0, qa_ * z * z + qd_));
  if (qa_ == 0) return std::sqrt(std::max(0.0, qd_)) * z;
  double half = 0.5 * z * s;
  if (qa_ > 0) {
    double r = std::sqrt(qa_);
    if (qd_ > 0) return half + qd_ / (2 * r) * std::asinh(z * r / std::sqrt(qd_));
    if (qd_ == 0) return half;
    // qd < 0: the spans keep |z| r >= sqrt(-qd); odd in z like the integral from 0.
    double x = std::max(1.0, std::abs(z) * r / std::sqrt(-qd_));
    return half + qd_ / (2 * r) * std::copysign(std::acosh(x), z);
  }
  double r = std::sqrt(-qa_);  // qa < 0 only with d > 0 on the spans
  return half + qd_ / (2 * r) * std::asin(std::clamp(z * r / std::sqrt(qd_), -1.0, 1.0));
}

double HyperboloidProfile::heightAtAreaFraction(double u) const {
  if (nSpans_ == 0) return lo_[0];
  double target = u * areaPerRadian();
  int i = (nSpans_ == 2 && target > spanArea_[0]) ? 1 : 0;
  if (i == 1) target -= spanArea_[0];
  double lo = lo_[i], hi = hi_[i], base = strip(lo_[i]);
  double z = lo + (spanArea_[i] > 0 ? std::clamp(target / spanArea_[i], 0.0, 1.0) : 0) * (hi - lo);
  double tol = 1e-15 * (std::abs(lo_[i]) + std::abs(hi_[i]));
  // Newton steps on the increasing strip(z) - base - target, whose derivative is sqrt(q); a step
  // leaving the bracket, or a zero derivative (a two-sheet vertex), falls back to bisection. A
  // fixed maximum count: no open loop.
  for (int it = 0; it < 80; ++it) {
    double h = strip(z) - base - target;
    if (h > 0)
      hi = z;
    else
      lo = z;
    double deriv = std::sqrt(std::max(0.0, qa_ * z * z + qd_));
    double next = deriv > 0 ? z - h / deriv : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - z) <= tol) return next;
    z = next;
  }
  return z;
}

double HyperboloidProfile::maxRadiusSquared() const {
  double m = 0;
  for (int i = 0; i < nSpans_; ++i) {
    m = std::max({m, radiusSquared(lo_[i]), radiusSquared(hi_[i])});
    // rho^2 is linear in z^2: an interior maximum only at z = 0 (an ellipsoid's equator).
    if (lo_[i] < 0 && hi_[i] > 0) m = std::max(m, radiusSquared(0));
  }
  return m;
}

}  // namespace candela
