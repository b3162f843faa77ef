#include "textures/checkerboard.h"

namespace candela {

namespace {

// 1 where floor(x) is odd. The parity is taken in floating point, so that coordinates beyond
// the int range never overflow a conversion.
Float oddCell(Float x) { return std::fmod(std::floor(x), Float(2)) != 0 ? 1 : 0; }

// The integral from 0 to x of oddCell (§11.6.2's BUMPINT): floor(x/2) whole periods, plus the
// part of the current period past its even half.
Float oddCellIntegral(Float x) {
  Float h = x / 2, fh = std::floor(h);
  return fh + 2 * std::max(h - fh - Float(0.5), Float(0));
}

// The average of oddCell over [x - d, x + d]; the point value when d = 0 (the draft divides by
// 2d regardless, 0/0 for a footprint flat in one direction).
Float oddCellAverage(Float x, Float d) {
  if (d == 0) return oddCell(x);
  return (oddCellIntegral(x + d) - oddCellIntegral(x - d)) / (2 * d);
}

}  // namespace

bool checkIsTex2(Float s, Float t) { return oddCell(std::floor(s) + std::floor(t)) != 0; }

bool checkIsTex2(const Point3f& p) {
  return oddCell(std::floor(p.x) + std::floor(p.y) + std::floor(p.z)) != 0;
}

Float checkerboardTex2Fraction(Float s, Float t, Float ds, Float dt) {
  if (!std::isfinite(s) || !std::isfinite(t)) return 0.5f;
  if (std::floor(s - ds) == std::floor(s + ds) && std::floor(t - dt) == std::floor(t + dt))
    return checkIsTex2(s, t) ? 1 : 0;
  // Wider than a whole period: the draft's clamp to the mean, dropping the box filter's residue.
  if (ds > 1 || dt > 1) return 0.5f;
  // A point is in a tex2 check when exactly one of floor(s), floor(t) is odd; the box is a
  // product, so the averages of the two 1D indicators combine as fs(1 - ft) + ft(1 - fs).
  Float fs = oddCellAverage(s, ds), ft = oddCellAverage(t, dt);
  return fs + ft - 2 * fs * ft;
}

namespace {
// A 32-bit mixing function (MurmurHash3's finalizer).
uint32_t mix32(uint32_t h) {
  h ^= h >> 16;
  h *= 0x85ebca6bu;
  h ^= h >> 13;
  h *= 0xc2b2ae35u;
  h ^= h >> 16;
  return h;
}
}  // namespace

Point2f supersampleJitter(const SurfaceInteraction& si, int index) {
  uint32_t h = mix32(floatToBits(si.p.x) ^
                     mix32(floatToBits(si.p.y) ^ mix32(floatToBits(si.p.z) ^ uint32_t(index))));
  uint32_t h2 = mix32(h ^ 0x9e3779b9u);
  // The top 24 bits as a float in [0, 1).
  return Point2f(Float(h >> 8) * 0x1p-24f, Float(h2 >> 8) * 0x1p-24f);
}

SurfaceInteraction shiftedInteraction(const SurfaceInteraction& si, Float dx, Float dy,
                                      Float shrink) {
  SurfaceInteraction r = si;
  r.p = si.p + si.dpdx * dx + si.dpdy * dy;
  r.uv = Point2f(si.uv.x + dx * si.dudx + dy * si.dudy, si.uv.y + dx * si.dvdx + dy * si.dvdy);
  r.dpdx = si.dpdx * shrink;
  r.dpdy = si.dpdy * shrink;
  r.dudx = si.dudx * shrink;
  r.dudy = si.dudy * shrink;
  r.dvdx = si.dvdx * shrink;
  r.dvdy = si.dvdy * shrink;
  return r;
}

}  // namespace candela
