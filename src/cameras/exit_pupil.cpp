#include "cameras/exit_pupil.h"

#include <algorithm>
#include <cmath>

namespace candela {

namespace {

constexpr int kAxisSamples = 256;       // along the line y = 0, to find the pupil
constexpr int kFineAxisSamples = 4096;  // when that finds nothing (a pupil under ~1% across)
constexpr int kColumns = 32;            // where the pupil's height is measured
constexpr int kGoldenSteps = 24;        // refine the tallest column
constexpr int kBisections = 20;         // an edge to a millionth of its bracket

struct PupilProbe {
  const LensSystem& lens;
  double r;
  bool passes(double x, double y) const {
    LensRay ray{{r, 0, 0}, {x - r, y, lens.rearZ()}};
    return lens.traceFromFilm(ray, nullptr);
  }
  // The last passing value between a passing a and a blocked b along x (on y = 0) or along y
  // (at x).
  double edgeAlongX(double a, double b) const {
    for (int k = 0; k < kBisections; ++k) {
      double m = 0.5 * (a + b);
      (passes(m, 0) ? a : b) = m;
    }
    return a;
  }
  double heightAt(double x, double top) const {
    if (passes(x, top)) return top;
    double a = 0, b = top;
    for (int k = 0; k < kBisections; ++k) {
      double m = 0.5 * (a + b);
      (passes(x, m) ? a : b) = m;
    }
    return a;
  }
};

}  // namespace

// The film point lies on the x axis of an axially symmetric system, so the pupil is symmetric
// about y = 0; an exit pupil bounded by circular apertures' images is convex (nearly so through
// refraction). A convex set symmetric about y = 0 contains (x, 0) whenever it contains (x, y):
// its x extent is that of its section by y = 0, found by sampling that line and bisecting the
// ends, and its height at each x is found by bisection from y = 0. The height is concave in x;
// its maximum is pinned by a golden-section search around the tallest of a row of columns.
bool boundPupilFrom(const LensSystem& lens, double r, double half, PupilBounds* out) {
  PupilProbe probe{lens, r};
  double x0 = 0, x1 = 0, step = 0;
  bool found = false;
  for (int n : {kAxisSamples, kFineAxisSamples}) {
    step = 2 * half / n;
    for (int i = 0; i < n; ++i) {
      double x = -half + (i + 0.5) * step;
      if (!probe.passes(x, 0)) continue;
      if (!found) x0 = x;
      x1 = x;
      found = true;
    }
    if (found) break;
  }
  if (!found) return false;
  x0 = x0 - step > -half ? probe.edgeAlongX(x0, x0 - step) : -half;
  x1 = x1 + step < half ? probe.edgeAlongX(x1, x1 + step) : half;

  double width = (x1 - x0) / kColumns, best = 0, bestX = x0;
  for (int i = 0; i < kColumns; ++i) {
    double x = x0 + (i + 0.5) * width, h = probe.heightAt(x, half);
    if (h > best) best = h, bestX = x;
  }
  // Golden-section search for the tallest point within a column of the tallest column.
  const double g = 0.5 * (std::sqrt(5.0) - 1);
  double a = std::max(x0, bestX - width), b = std::min(x1, bestX + width);
  double c = b - g * (b - a), d = a + g * (b - a);
  double hc = probe.heightAt(c, half), hd = probe.heightAt(d, half);
  for (int k = 0; k < kGoldenSteps; ++k) {
    if (hc > hd) {
      b = d, d = c, hd = hc;
      c = b - g * (b - a), hc = probe.heightAt(c, half);
    } else {
      a = c, c = d, hc = hd;
      d = a + g * (b - a), hd = probe.heightAt(d, half);
    }
  }
  double y1 = std::max({best, hc, hd});
  *out = {x0, x1, -y1, y1};
  return true;
}

ExitPupil::ExitPupil(const LensSystem& lens, double filmRadius, int intervals)
    : filmRadius_(filmRadius), rearZ_(lens.rearZ()) {
  const double half = 1.5 * lens.rearApertureRadius();
  // Film points at both ends of each interval (shared between neighbours).
  std::vector<PupilBounds> at(intervals + 1);
  std::vector<bool> found(at.size());
  for (size_t k = 0; k < at.size(); ++k)
    found[k] = boundPupilFrom(lens, filmRadius * double(k) / double(intervals), half, &at[k]);
  // The pupil's edges move smoothly, nearly linearly, with the film point: a margin of a
  // thousandth of the rear aperture covers them between the ends, and the pupil's departure
  // from convexity.
  const double margin = 1e-3 * lens.rearApertureRadius();
  bounds_.resize(intervals);
  for (int i = 0; i < intervals; ++i) {
    PupilBounds u{1e300, -1e300, 1e300, -1e300};
    bool any = false;
    for (int k = i; k <= i + 1; ++k) {
      if (!found[k]) continue;
      any = true;
      u = {std::min(u.x0, at[k].x0), std::max(u.x1, at[k].x1), std::min(u.y0, at[k].y0),
           std::max(u.y1, at[k].y1)};
    }
    // Nothing found: the whole search square (rays are then mostly blocked, never missed).
    bounds_[i] = any ? PupilBounds{u.x0 - margin, u.x1 + margin, u.y0 - margin, u.y1 + margin}
                     : PupilBounds{-half, half, -half, half};
  }
}

const PupilBounds& ExitPupil::boundsAt(double r) const {
  int n = int(bounds_.size());
  int i = filmRadius_ > 0 ? int(r / filmRadius_ * n) : 0;
  return bounds_[std::clamp(i, 0, n - 1)];
}

LensVector ExitPupil::sample(double filmX, double filmY, double u0, double u1, double* area) const {
  double r = std::sqrt(filmX * filmX + filmY * filmY);
  const PupilBounds& b = boundsAt(r);
  *area = b.area();
  double x = b.x0 + u0 * (b.x1 - b.x0), y = b.y0 + u1 * (b.y1 - b.y0);
  // The bounds are for a film point on +x: turn them to the film point's angle.
  double c = r > 0 ? filmX / r : 1, s = r > 0 ? filmY / r : 0;
  return {c * x - s * y, s * x + c * y, rearZ_};
}

}  // namespace candela
