// pbrt-v3's roughness parameters for a material's microfacet lobes (pbrt 3e §9.2): roughness
// textures along u and v and "remaproughness", which maps them to the Trowbridge-Reitz alphas
// through roughnessToAlpha (pbrt 3e §8.4.2); without it they are the alphas themselves.
#pragma once

#include "core/memory.h"
#include "reflection/trowbridge_reitz.h"
#include "textures/texture.h"

namespace candela {

struct TrowbridgeReitzRoughness {
  const Texture<Float>* u = nullptr;
  const Texture<Float>* v = nullptr;
  bool remap = true;

  // The distribution at si, made in the arena.
  const TrowbridgeReitzDistribution* distribution(const SurfaceInteraction& si,
                                                  MemoryArena& arena) const {
    Float au = u->evaluate(si), av = v->evaluate(si);
    if (remap) au = roughnessToAlpha(au), av = roughnessToAlpha(av);
    return arena.make<TrowbridgeReitzDistribution>(au, av);
  }
  // Both roughnesses 0 at si: pbrt-v3's glass is then perfectly specular.
  bool smoothAt(const SurfaceInteraction& si) const {
    return u->evaluate(si) == 0 && v->evaluate(si) == 0;
  }
};

}  // namespace candela
