#include "media/aggregate_volume.h"

#include <algorithm>

namespace candela {

AggregateVolume::AggregateVolume(std::vector<std::unique_ptr<Medium>> regions)
    : regions_(std::move(regions)) {
  for (const auto& r : regions_) bound_ = unionOf(bound_, r->worldBound());
}

bool AggregateVolume::intersectP(const Ray& ray, Float* t0, Float* t1) const {
  Float lo = kInfinity, hi = -kInfinity;
  for (const auto& r : regions_) {
    Float a, b;
    if (!r->intersectP(ray, &a, &b)) continue;
    lo = std::min(lo, a);
    hi = std::max(hi, b);
  }
  if (!(hi > lo)) return false;
  *t0 = lo;
  *t1 = hi;
  return true;
}

MediumPoint AggregateVolume::at(const Point3f& p, Float time) const {
  MediumPoint sum;
  for (const auto& r : regions_) {
    MediumPoint m = r->at(p, time);
    sum.sigmaA += m.sigmaA;
    sum.sigmaS += m.sigmaS;
    sum.Le += m.Le;
  }
  return sum;
}

PhaseFunction AggregateVolume::phase(const Point3f& p, Float time) const {
  const Medium* strongest = nullptr;
  Float best = 0;
  for (const auto& r : regions_) {
    Float s = r->at(p, time).sigmaS.average();
    if (s > best) {
      best = s;
      strongest = r.get();
    }
  }
  return strongest ? strongest->phase(p, time) : PhaseFunction::isotropic();
}

Spectrum AggregateVolume::opticalDepth(const Ray& ray, Float t0, Float t1, Float stepSize,
                                       Float offset) const {
  Spectrum tau(0);
  for (const auto& r : regions_) tau += r->opticalDepth(ray, t0, t1, stepSize, offset);
  return tau;
}

Spectrum AggregateVolume::majorant(const Ray& ray, Float t0, Float t1) const {
  Spectrum m(0);
  for (const auto& r : regions_) m += r->majorant(ray, t0, t1);
  return m;
}

bool AggregateVolume::emits() const {
  return std::any_of(regions_.begin(), regions_.end(), [](const auto& r) { return r->emits(); });
}

}  // namespace candela
