// Materials turn a surface point into a BSDF (lrt draft ch. 10). BSDFs live in the caller's
// per-sample arena. Every material may carry a bump map (lrt draft §10.10), applied to the
// shading frame before its BxDFs are chosen.
#pragma once

#include <new>
#include <type_traits>

#include "core/memory.h"
#include "reflection/bsdf.h"
#include "textures/texture.h"

namespace candela {

class SubsurfaceScattering;

// Room for a material's bumped copy of a hit point, left uninitialised until a bump map writes
// it. (std::optional would do, but GCC 12 zeroes all of its ~250 bytes on construction, GCC PR
// 86173, on every hit of every material.)
class BumpedPointStorage {
 public:
  BumpedPointStorage() {}
  const SurfaceInteraction& emplace(const SurfaceInteraction& si) {
    return *new (bytes_) SurfaceInteraction(si);
  }

 private:
  static_assert(std::is_trivially_destructible_v<SurfaceInteraction>, "never destroyed");
  alignas(SurfaceInteraction) unsigned char bytes_[sizeof(SurfaceInteraction)];
};

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
  // si itself without a bump map; else si with the bumped shading frame, made in *storage.
  const SurfaceInteraction& shadingPoint(const SurfaceInteraction& si,
                                         BumpedPointStorage* storage) const {
    return bump_ ? bumpedPoint(si, storage) : si;
  }

 private:
  const SurfaceInteraction& bumpedPoint(const SurfaceInteraction& si,
                                        BumpedPointStorage* storage) const;

  const Texture<Float>* bump_;
};

}  // namespace candela
