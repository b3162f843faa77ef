// Test helper: tail probabilities for the statistical tests (chi-square goodness of fit, Poisson
// counts, Student's t for means of few replicates) and the Šidák per-case significance.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace candela::stats {

namespace detail {
// Both parts of the regularised incomplete gamma function: the series of P(a, x) for x < a + 1,
// and the continued fraction of Q(a, x) (modified Lentz) otherwise, each to double precision and
// each the accurate one in its range; the other is 1 minus it.
struct IncompleteGamma {
  double p, q;
};
inline IncompleteGamma incompleteGamma(double a, double x) {
  if (x <= 0) return {0, 1};
  double lnPrefix = a * std::log(x) - x - std::lgamma(a);
  if (x < a + 1) {
    double term = 1 / a, sum = term;
    for (int n = 1; n < 100000; ++n) {
      term *= x / (a + n);
      sum += term;
      if (std::abs(term) < std::abs(sum) * 1e-16) break;
    }
    double p = std::min(1.0, sum * std::exp(lnPrefix));
    return {p, 1 - p};
  }
  const double tiny = 1e-300;
  double b = x + 1 - a, c = 1 / tiny, d = 1 / b, h = d;
  for (int n = 1; n < 100000; ++n) {
    double an = -n * (n - a);
    b += 2;
    d = an * d + b;
    if (std::abs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1 / d;
    double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1) < 1e-16) break;
  }
  double q = std::min(1.0, std::exp(lnPrefix) * h);
  return {1 - q, q};
}
}  // namespace detail

// Regularised lower and upper incomplete gamma functions P(a, x) and Q(a, x) = 1 - P(a, x).
inline double gammaP(double a, double x) { return detail::incompleteGamma(a, x).p; }
inline double gammaQ(double a, double x) { return detail::incompleteGamma(a, x).q; }

// P(X >= x) for X chi-square with dof degrees of freedom.
inline double chiSquareSurvival(double x, int dof) { return gammaQ(0.5 * dof, 0.5 * x); }
// P(X >= k) for X Poisson with mean lambda.
inline double poissonUpperTail(int64_t k, double lambda) {
  if (k <= 0) return 1;
  if (lambda <= 0) return 0;
  return gammaP(double(k), lambda);
}
namespace detail {
// The continued fraction of the regularised incomplete beta function I_x(a, b) (modified Lentz),
// which converges fast for x < (a + 1) / (a + b + 2).
inline double betaContinuedFraction(double a, double b, double x) {
  constexpr double tiny = 1e-300;
  auto guard = [](double v) { return std::abs(v) < tiny ? tiny : v; };
  double c = 1, d = 1 / guard(1 - (a + b) * x / (a + 1));
  double f = d;
  for (int m = 1; m <= 10000; ++m) {
    // The even then the odd coefficient of the fraction.
    const double even = m * (b - m) * x / ((a + 2 * m - 1) * (a + 2 * m));
    d = 1 / guard(1 + even * d);
    c = guard(1 + even / c);
    f *= d * c;
    const double odd = -(a + m) * (a + b + m) * x / ((a + 2 * m) * (a + 2 * m + 1));
    d = 1 / guard(1 + odd * d);
    c = guard(1 + odd / c);
    f *= d * c;
    if (std::abs(d * c - 1) < 1e-15) break;
  }
  return f;
}
}  // namespace detail

// The regularised incomplete beta function I_x(a, b), a, b > 0; by the continued fraction on the
// side of the mean where it converges, and I_x(a, b) = 1 - I_{1-x}(b, a) on the other.
inline double incompleteBeta(double a, double b, double x) {
  if (x <= 0) return 0;
  if (x >= 1) return 1;
  const double front = std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) +
                                a * std::log(x) + b * std::log1p(-x));
  if (x < (a + 1) / (a + b + 2)) return front * detail::betaContinuedFraction(a, b, x) / a;
  return 1 - front * detail::betaContinuedFraction(b, a, 1 - x) / b;
}

// P(|T| >= |t|) for T Student's t with dof degrees of freedom (any real dof > 0, as Welch's
// approximation gives).
inline double studentTwoSidedTail(double t, double dof) {
  return incompleteBeta(0.5 * dof, 0.5, dof / (dof + t * t));
}

// P(|Z| >= |z|) for Z standard normal.
inline double normalTwoSidedTail(double z) { return std::erfc(std::abs(z) / std::sqrt(2.0)); }
// The per-case significance that keeps the family-wise error at alpha over m independent cases.
inline double sidak(double alpha, int m) { return 1 - std::pow(1 - alpha, 1.0 / m); }

}  // namespace candela::stats
