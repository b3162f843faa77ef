#include "reflection/fourier_series.h"

#include <algorithm>
#include <cmath>

namespace candela {

Float evaluateFourier(const Float* a, int m, double cosPhi) {
  // Double precision: the recurrence amplifies rounding by about k at high orders.
  double value = 0, cosPrev = cosPhi, cosK = 1;
  for (int k = 0; k < m; ++k) {
    value += double(a[k]) * cosK;
    double next = 2 * cosPhi * cosK - cosPrev;
    cosPrev = cosK;
    cosK = next;
  }
  return Float(value);
}

bool sampleFourier(const Float* a, int m, Float u, Float* phiOut, Float* value, Float* pdf) {
  if (m <= 0 || !(a[0] > 0)) return false;
  bool negative = u >= Float(0.5);
  double v = negative ? 2 * double(u) - 1 : 2 * double(u);
  // The integral over [0, phi] is a_0 phi + sum_k a_k sin(k phi) / k, pi a_0 at phi = pi.
  double goal = v * M_PI * double(a[0]);
  double lo = 0, hi = M_PI, phi = v * M_PI, f = 0;
  for (int iter = 0; iter < 100; ++iter) {
    double c = std::cos(phi), s = std::sin(phi);
    // cos and sin of k phi by the same recurrence (Chebyshev polynomials of both kinds).
    double cosPrev = c, cosK = 1, sinPrev = -s, sinK = 0;
    double F = 0;
    f = 0;
    for (int k = 0; k < m; ++k) {
      f += double(a[k]) * cosK;
      F += k == 0 ? double(a[0]) * phi : double(a[k]) * sinK / k;
      double cosNext = 2 * c * cosK - cosPrev, sinNext = 2 * c * sinK - sinPrev;
      cosPrev = cosK;
      cosK = cosNext;
      sinPrev = sinK;
      sinK = sinNext;
    }
    F -= goal;
    if (std::abs(F) < 1e-7 * std::max(goal, 1e-7) || hi - lo < 1e-9) break;
    if (F > 0)
      hi = phi;
    else
      lo = phi;
    double next = f > 0 ? phi - F / f : -1;
    phi = next > lo && next < hi ? next : (lo + hi) / 2;
  }
  *phiOut = Float(negative ? -phi : phi);
  // The series where the search stopped (the loop's last value may precede its last step).
  *value = evaluateFourier(a, m, std::cos(phi));
  *pdf = *value / Float(2 * M_PI * double(a[0]));
  return true;
}

}  // namespace candela
