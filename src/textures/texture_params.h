// Reading a texture's mapping from its parameters (pbrt-v2's names and defaults):
//   "string mapping" "uv" (default) | "spherical" | "cylindrical" | "planar";
//   uv: "float uscale" 1, "vscale" 1, "udelta" 0, "vdelta" 0 (lrt's su, sv, du, dv also accepted;
//       the pbrt-v2 name wins when both are given);
//   planar: "vector v1" (1 0 0), "vector v2" (0 1 0), "float udelta" 0, "vdelta" 0;
//   spherical, cylindrical and planar work in texture space (worldToTexture).
#pragma once

#include <memory>

#include "core/paramset.h"
#include "textures/mapping.h"

namespace candela {

// Throws SceneError (at the "mapping" parameter, or loc) for an unknown mapping, listing the known.
std::unique_ptr<TextureMapping2D> createMapping2D(const ParamSet& params,
                                                  const Transform& worldToTexture,
                                                  const FileLoc& loc);

}  // namespace candela
