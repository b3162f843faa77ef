// The profile of pbrt 2e/3e's hyperboloid (§3.5.3 of both): the surface of revolution
// x^2 + y^2 = d + k z^2 between two heights, and how pbrt-v2/v3 choose k and d from the points
// p1 and p2 of a "hyperboloid" statement.
//
// Written with rho^2 = d + k z^2 the one equation covers every case the fit can produce: a
// hyperboloid of one sheet (k > 0, d > 0, waist radius sqrt(d) at z = 0), a cone with its apex at
// the origin (d = 0), a cylinder (k = 0), part of an ellipsoid (k < 0) or of a hyperboloid of two
// sheets (d < 0). Where d + k z^2 < 0 there is no surface, so the heights holding surface are up
// to two intervals ("spans") of [zMin, zMax].
#pragma once

namespace candela {

struct HyperboloidFit {
  // The statement's points, swapped when p2 lies at z = 0 (pbrt's fit divides by p2.z); the
  // parameterisation then measures v from the swapped p1.
  double p1[3], p2[3];
  double k = 0, d = 0;
  // The fit is a pair of planes z = +-|p2.z| (p1.z = 3 p2.z): no surface between the heights.
  bool degenerate = false;
};

// pbrt-v2/v3's fit: the quadric a (x^2 + y^2) - c z^2 = 1 through p2 and q = p1 + 2 m (p2 - p1)
// for the first m = 1, 2, ... for which the 2x2 system has a solution (pbrt 3e's hyperboloid
// constructor), i.e. d = 1 / a, k = c / a. p1 itself is on the surface only when the segment is a
// ruling of it. When no m works the line passes through the origin: the cone it sweeps (d = 0).
// p1.z and p2.z must differ.
HyperboloidFit fitHyperboloid(const double p1[3], const double p2[3]);

class HyperboloidProfile {
 public:
  HyperboloidProfile(double k, double d, double zMin, double zMax);
  double radiusSquared(double z) const { return d_ + k_ * z * z; }
  int spanCount() const { return nSpans_; }
  double spanLow(int i) const { return lo_[i]; }
  double spanHigh(int i) const { return hi_[i]; }
  // The area of the full (2 pi) surface between zMin and zMax divided by 2 pi: the integral of
  // rho sqrt(1 + rho'^2) = sqrt(d + k (1 + k) z^2) over the spans.
  double areaPerRadian() const { return spanArea_[0] + spanArea_[1]; }
  // The height whose share of areaPerRadian lies below it is u (inverse of the area CDF).
  double heightAtAreaFraction(double u) const;
  // The largest rho^2 over the spans (0 without surface).
  double maxRadiusSquared() const;

 private:
  // An antiderivative of sqrt(qa z^2 + qd) in z.
  double strip(double z) const;
  double k_, d_, qa_, qd_;
  int nSpans_ = 0;
  double lo_[2] = {0, 0}, hi_[2] = {0, 0}, spanArea_[2] = {0, 0};
};

}  // namespace candela
