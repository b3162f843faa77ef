#include "reflection/catmull_rom.h"

#include <algorithm>
#include <cmath>

namespace candela {

namespace {

// The last interval [nodes[i], nodes[i + 1]] that starts at or before x (so that x on a repeated
// node falls in the interval after the repeat).
int findInterval(std::span<const Float> nodes, Float x) {
  auto it = std::upper_bound(nodes.begin(), nodes.end(), x);
  int i = int(it - nodes.begin()) - 1;
  return std::clamp(i, 0, int(nodes.size()) - 2);
}

// Hermite end values and derivatives (in units of the interval's width) of the interval starting
// at node i, with value(k) the data at node k.
template <typename Value>
void hermiteEnds(std::span<const Float> nodes, int i, const Value& value, Float* f0, Float* f1,
                 Float* d0, Float* d1) {
  int n = int(nodes.size());
  Float x0 = nodes[size_t(i)], x1 = nodes[size_t(i + 1)], width = x1 - x0;
  *f0 = value(i);
  *f1 = value(i + 1);
  if (i > 0 && x1 > nodes[size_t(i - 1)])
    *d0 = width * (*f1 - value(i - 1)) / (x1 - nodes[size_t(i - 1)]);
  else
    *d0 = *f1 - *f0;
  if (i + 2 < n && nodes[size_t(i + 2)] > x0)
    *d1 = width * (value(i + 2) - *f0) / (nodes[size_t(i + 2)] - x0);
  else
    *d1 = *f1 - *f0;
}

// Integral over [0, t] of the Hermite cubic with ends (f0, f1) and derivatives (d0, d1), and the
// cubic itself: p(t) = f0 + d0 t + (3 (f1 - f0) - 2 d0 - d1) t^2 + (2 (f0 - f1) + d0 + d1) t^3.
Float hermiteIntegral(Float f0, Float f1, Float d0, Float d1, Float t) {
  Float c2 = 3 * (f1 - f0) - 2 * d0 - d1, c3 = 2 * (f0 - f1) + d0 + d1;
  return t * (f0 + t * (d0 / 2 + t * (c2 / 3 + t * (c3 / 4))));
}
Float hermiteValue(Float f0, Float f1, Float d0, Float d1, Float t) {
  Float c2 = 3 * (f1 - f0) - 2 * d0 - d1, c3 = 2 * (f0 - f1) + d0 + d1;
  return f0 + t * (d0 + t * (c2 + t * c3));
}

}  // namespace

bool catmullRomWeights(std::span<const Float> nodes, Float x, int* offset, Float weights[4]) {
  int n = int(nodes.size());
  if (n < 2 || !(x >= nodes.front() && x <= nodes.back())) return false;
  int i = findInterval(nodes, x);
  *offset = i - 1;
  Float x0 = nodes[size_t(i)], x1 = nodes[size_t(i + 1)], width = x1 - x0;
  Float t = width > 0 ? (x - x0) / width : 0, t2 = t * t, t3 = t2 * t;
  // Hermite basis: p = h00 f0 + h01 f1 + h10 d0 + h11 d1, with the derivatives d0, d1 written
  // as differences of the data (hermiteEnds).
  Float h00 = 2 * t3 - 3 * t2 + 1, h01 = -2 * t3 + 3 * t2, h10 = t3 - 2 * t2 + t, h11 = t3 - t2;
  weights[0] = 0;
  weights[1] = h00;
  weights[2] = h01;
  weights[3] = 0;
  if (i > 0 && x1 > nodes[size_t(i - 1)]) {
    Float s = width / (x1 - nodes[size_t(i - 1)]);
    weights[0] -= h10 * s;
    weights[2] += h10 * s;
  } else {
    weights[1] -= h10;
    weights[2] += h10;
  }
  if (i + 2 < n && nodes[size_t(i + 2)] > x0) {
    Float s = width / (nodes[size_t(i + 2)] - x0);
    weights[3] += h11 * s;
    weights[1] -= h11 * s;
  } else {
    weights[2] += h11;
    weights[1] -= h11;
  }
  return true;
}

Float integrateCatmullRom(std::span<const Float> nodes, std::span<const Float> values,
                          std::span<Float> cdf) {
  double sum = 0;
  cdf[0] = 0;
  auto value = [&](int k) { return values[size_t(k)]; };
  for (int i = 0; i + 1 < int(nodes.size()); ++i) {
    Float f0, f1, d0, d1;
    hermiteEnds(nodes, i, value, &f0, &f1, &d0, &d1);
    Float width = nodes[size_t(i + 1)] - nodes[size_t(i)];
    sum += double(width) * double(hermiteIntegral(f0, f1, d0, d1, 1));
    cdf[size_t(i + 1)] = Float(sum);
  }
  return Float(sum);
}

namespace {

// The row at alpha: blend weights over the parameter nodes.
struct BlendedRow {
  const CatmullRomRows& rows;
  int offset = 0;
  Float w[4] = {0, 0, 0, 0};
  Float at(std::span<const Float> table, int k) const {
    size_t n = rows.nodes.size();
    Float v = 0;
    for (int r = 0; r < 4; ++r)
      if (w[r] != 0) v += w[r] * table[size_t(offset + r) * n + size_t(k)];
    return v;
  }
};

}  // namespace

bool sampleCatmullRom2D(const CatmullRomRows& rows, Float alpha, Float u, Float* x, Float* value,
                        Float* pdf) {
  BlendedRow row{rows};
  if (!catmullRomWeights(rows.paramNodes, alpha, &row.offset, row.w)) return false;
  std::span<const Float> nodes = rows.nodes;
  int n = int(nodes.size());
  Float total = row.at(rows.cdf, n - 1);
  if (!(total > 0)) return false;
  Float target = u * total;
  // The last interval whose integral up to its start does not exceed the target: this skips
  // zero-width intervals, whose integrals are equal at both ends.
  int lo = 0, hi = n - 2;
  while (lo < hi) {
    int mid = (lo + hi + 1) / 2;
    if (row.at(rows.cdf, mid) <= target)
      lo = mid;
    else
      hi = mid - 1;
  }
  int i = lo;
  Float x0 = nodes[size_t(i)], width = nodes[size_t(i + 1)] - x0;
  if (!(width > 0)) return false;
  Float f0, f1, d0, d1;
  hermiteEnds(
      nodes, i, [&](int k) { return row.at(rows.values, k); }, &f0, &f1, &d0, &d1);
  // Invert the interval's integral (in units of its width) by Newton's method, falling back
  // to bisection whenever a step leaves the bracket.
  Float goal = (target - row.at(rows.cdf, i)) / width;
  Float a = 0, b = 1, t;
  if (f0 != f1)
    t = (std::sqrt(std::max(Float(0), f0 * f0 + 2 * goal * (f1 - f0))) - f0) / (f1 - f0);
  else
    t = f0 > 0 ? goal / f0 : Float(0.5);
  if (!(t >= a && t <= b)) t = Float(0.5);
  Float fhat = 0;
  for (int iter = 0; iter < 64; ++iter) {
    Float F = hermiteIntegral(f0, f1, d0, d1, t) - goal;
    fhat = hermiteValue(f0, f1, d0, d1, t);
    if (std::abs(F) < Float(1e-6) * std::max(goal, Float(1e-6)) || b - a < Float(1e-7)) break;
    if (F > 0)
      b = t;
    else
      a = t;
    Float next = fhat != 0 ? t - F / fhat : Float(-1);
    t = next > a && next < b ? next : (a + b) / 2;
  }
  *x = x0 + width * t;
  *value = hermiteValue(f0, f1, d0, d1, t);
  *pdf = *value / total;
  return true;
}

Float evaluateCatmullRom2D(const CatmullRomRows& rows, Float alpha, Float x, Float* integral) {
  *integral = 0;
  int offA, offX;
  Float wa[4], wx[4];
  if (!catmullRomWeights(rows.paramNodes, alpha, &offA, wa) ||
      !catmullRomWeights(rows.nodes, x, &offX, wx))
    return 0;
  size_t n = rows.nodes.size();
  Float v = 0, total = 0;
  for (int a = 0; a < 4; ++a) {
    if (wa[a] == 0) continue;
    size_t r = size_t(offA + a) * n;
    total += wa[a] * rows.cdf[r + n - 1];
    for (int b = 0; b < 4; ++b)
      if (wx[b] != 0) v += wa[a] * wx[b] * rows.values[r + size_t(offX + b)];
  }
  *integral = total;
  return v;
}

}  // namespace candela
