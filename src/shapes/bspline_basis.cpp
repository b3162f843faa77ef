#include "shapes/bspline_basis.h"

#include <algorithm>

namespace candela {

namespace {

// The recursion's a / b with 0 / 0 taken as 0 (The NURBS Book, §2.2): a zero-width interval only
// ever multiplies a function that is identically zero. Knots are nondecreasing, so b >= 0.
double ratio(double a, double b) { return b > 0 ? a / b : 0.0; }

}  // namespace

int findKnotSpan(const std::vector<double>& knots, int order, int count, double t, bool fromLeft) {
  auto first = knots.begin() + (order - 1), last = knots.begin() + count;
  if (fromLeft) {
    // The last span start in [k - 1, count - 1] below t, which ends at or above t (t <= U[count]).
    int s = int(std::lower_bound(first, last, t) - knots.begin()) - 1;
    s = std::max(s, order - 1);
    // At t = U[k - 1] the first span may be empty (repeated knots): step on to a real one.
    while (s < count - 1 && knots[s] == knots[s + 1]) ++s;
    return s;
  }
  // The last span start in [k - 1, count - 1] not above t; a binary search, as A2.1.
  int s = int(std::upper_bound(first, last, t) - knots.begin()) - 1;
  s = std::max(s, order - 1);
  // At t = U[count] with repeated end knots the span found is empty: step back to a real one.
  while (s > order - 1 && knots[s] == knots[s + 1]) --s;
  return s;
}

BasisAt evaluateBasis(const std::vector<double>& knots, int order, int count, double t,
                      bool fromLeft) {
  const int p = order - 1, s = findKnotSpan(knots, order, count, t, fromLeft);
  BasisAt out;
  out.first = s - p;
  // n[r] holds N_{s - p + r, j} while the degree j rises from 0 to p (Cox-de Boor, eq. 2.5). At
  // degree j only r >= p - j can be nonzero; going up in r, n[r + 1] is still of degree j - 1.
  std::vector<double> n(order, 0.0), lower;
  n[p] = 1;
  for (int j = 1; j <= p; ++j) {
    if (j == p) lower = n;  // degree p - 1, for the derivative
    for (int r = p - j; r <= p; ++r) {
      int i = s - p + r;
      double left = ratio(t - knots[i], knots[i + j] - knots[i]) * n[r];
      double right =
          r < p ? ratio(knots[i + j + 1] - t, knots[i + j + 1] - knots[i + 1]) * n[r + 1] : 0.0;
      n[r] = left + right;
    }
  }
  out.value = std::move(n);
  // N'_{i,p} = p (N_{i,p-1} / (U[i+p] - U[i]) - N_{i+1,p-1} / (U[i+p+1] - U[i+1])) (eq. 2.7);
  // order 1 is piecewise constant.
  out.derivative.assign(order, 0.0);
  if (p > 0)
    for (int r = 0; r <= p; ++r) {
      int i = s - p + r;
      double next = r < p ? ratio(lower[r + 1], knots[i + p + 1] - knots[i + 1]) : 0.0;
      out.derivative[r] = p * (ratio(lower[r], knots[i + p] - knots[i]) - next);
    }
  return out;
}

}  // namespace candela
