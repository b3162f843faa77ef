// Bump mapping (lrt draft §10.10): a scalar displacement d(u, v) along the shading normal
// perturbs the shading frame as if the surface were p' = p + d n, without moving p.
#pragma once

#include "core/interaction.h"
#include "textures/texture.h"

namespace candela {

// The step in u (and v) for the finite differences: half the screen-space footprint,
// .5 (|du/dx| + |du/dy|), or .01 when the point has no ray differentials. The draft tested dudx
// twice and never dvdx (seed-000 inventory §24); here each direction falls back on its own.
Float bumpStepU(const SurfaceInteraction& si);
Float bumpStepV(const SurfaceInteraction& si);

// si with the shading frame of the displaced surface: dp'/du = dp/du + (dd/du) n + d dn/du
// (dn/du's product with d kept, as the draft does), the shading normal their cross product,
// turned to the geometric normal's side.
SurfaceInteraction bump(const Texture<Float>& displacement, const SurfaceInteraction& si);

}  // namespace candela
