// Materials turn a surface point into a BSDF (lrt draft ch. 10). BSDFs live in the caller's
// per-sample arena. Every material may carry a bump map (lrt draft §10.10), applied to the
// shading frame before its BxDFs are chosen.
#pragma once

#include "core/memory.h"
#include "reflection/bsdf.h"
#include "textures/texture.h"

namespace candela {

class SubsurfaceScattering;

class Material {
 public:
  explicit Material(const Texture<Float>* bump = nullptr) : bump_(bump) {}
  virtual ~Material() = default;
  virtual const BSDF* getBSDF(const SurfaceInteraction& si, MemoryArena& arena) const = 0;
  // Whether some BSDF it makes may have a perfectly specular component (photon mapping builds
  // no caustic map without one). Conservative: true may still give none.
  virtual bool maybeSpecular() const { return false; }
  const Texture<Float>* bumpMap() const { return bump_; }
  // The medium under the surface for the dipole integrator (pbrt 2e §16.5): null for every
  // material but "subsurface" and "kdsubsurface".
  virtual const SubsurfaceScattering* subsurface() const { return nullptr; }

 protected:
  // si itself without a bump map; else si with the bumped shading frame, written to *storage.
  const SurfaceInteraction& shadingPoint(const SurfaceInteraction& si,
                                         SurfaceInteraction* storage) const;

 private:
  const Texture<Float>* bump_;
};

}  // namespace candela
