// Bounds on a lens system's exit pupil (pbrt 3e §6.4.5): for film points at a distance from the
// axis, the region of the plane of the rear vertex through which rays from them pass the whole
// system. The system is symmetric about its axis, so the bounds are computed for film points on
// +x and rotated to the film point's angle when sampling; they are kept for a number of radial
// intervals covering the film out to its corners.
#pragma once

#include <vector>

#include "cameras/lens_system.h"

namespace candela {

struct PupilBounds {
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  double area() const { return (x1 - x0) * (y1 - y0); }
  bool contains(double x, double y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
};

class ExitPupil {
 public:
  // filmRadius: the film's half diagonal (m); intervals: how many radial intervals.
  ExitPupil(const LensSystem& lens, double filmRadius, int intervals = 64);

  // The bounds for film points at distance r from the axis along +x.
  const PupilBounds& boundsAt(double r) const;
  int intervals() const { return int(bounds_.size()); }
  const PupilBounds& interval(int i) const { return bounds_[i]; }
  // A point on the rear plane uniform over the bounds for the film point (x, y), rotated to its
  // angle; *area is the bounds' area (the sampling density is 1 / area).
  LensVector sample(double filmX, double filmY, double u0, double u1, double* area) const;

 private:
  double filmRadius_, rearZ_;
  std::vector<PupilBounds> bounds_;
};

// The bounds of the pupil seen from the single film point (r, 0, 0), searched within a square of
// half-width `half` around the axis. Returns false when none is found (a pupil narrower than
// about 1/2000 of the square).
bool boundPupilFrom(const LensSystem& lens, double r, double half, PupilBounds* out);

}  // namespace candela
