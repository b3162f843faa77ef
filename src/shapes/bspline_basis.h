// B-spline basis functions and their first derivatives (Piegl & Tiller, The NURBS Book, §2.2-2.3,
// eq. 2.5 and 2.7), in double: the one-dimensional building block of the "nurbs" shape.
//
// Conventions: `count` functions N_0 .. N_{count-1} of order k (degree k - 1) over count + k
// nondecreasing knots U. The valid parameter range, where the functions sum to one, is
// [U[k - 1], U[count]].
#pragma once

#include <vector>

namespace candela {

// The order-k functions that can be nonzero at one parameter: N_first .. N_{first + k - 1}.
struct BasisAt {
  int first = 0;
  std::vector<double> value;       // k entries
  std::vector<double> derivative;  // k entries, dN/dt
};

// The knot span s (k - 1 <= s <= count - 1) with U[s] <= t < U[s + 1]; at the end of the valid
// range, t = U[count], the last nonempty span. With fromLeft, the one with U[s] < t <= U[s + 1]
// (at the start of the range, the first nonempty span): the two differ only at knots. Requires a
// nonempty valid range and t inside it.
int findKnotSpan(const std::vector<double>& knots, int order, int count, double t,
                 bool fromLeft = false);

// The nonzero basis functions and their derivatives at t in the valid range. At a knot the
// functions and derivatives are those of the span to its right (of the last span at the end), or
// with fromLeft of the span to its left (of the first at the start): the limits from either side.
BasisAt evaluateBasis(const std::vector<double>& knots, int order, int count, double t,
                      bool fromLeft = false);

}  // namespace candela
