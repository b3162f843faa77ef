// pbrt-v3's "homogeneous" named medium (pbrt 3e §11.3.3): the same σa, σs and Henyey–Greenstein
// g everywhere; its extent is set by the shapes whose MediumInterface names it, so it fills all
// space, and its transmittance has the closed form exp(-σt d).
#pragma once

#include "media/medium.h"

namespace candela {

class HomogeneousMedium : public Medium {
 public:
  // sigmaA, sigmaS per world unit (the "scale" parameter already applied); g in (-1, 1).
  HomogeneousMedium(const Spectrum& sigmaA, const Spectrum& sigmaS, Float g);
  Bounds3f worldBound() const override;
  bool intersectP(const Ray& ray, Float* t0, Float* t1) const override;
  MediumPoint at(const Point3f&, Float) const override { return {sigmaA_, sigmaS_, Spectrum(0)}; }
  PhaseFunction phase(const Point3f&, Float) const override { return phase_; }
  Spectrum opticalDepth(const Ray& ray, Float t0, Float t1, Float stepSize,
                        Float offset) const override;
  Spectrum majorant(const Ray&, Float, Float) const override { return sigmaA_ + sigmaS_; }
  bool isHomogeneous() const override { return true; }

 private:
  Spectrum sigmaA_, sigmaS_;
  PhaseFunction phase_;
};

}  // namespace candela
