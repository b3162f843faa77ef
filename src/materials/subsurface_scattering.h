// What a translucent material tells the dipole integrator (pbrt 2e §16.5): the medium under its
// surface at a shading point.
#pragma once

#include "core/interaction.h"
#include "reflection/dipole.h"

namespace candela {

class SubsurfaceScattering {
 public:
  virtual ~SubsurfaceScattering() = default;
  // sigma_a, sigma_s' (non-negative) and eta at si (its textures evaluated there).
  virtual BSSRDFCoefficients coefficients(const SurfaceInteraction& si) const = 0;
};

}  // namespace candela
