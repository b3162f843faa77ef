// Reading a texture's mapping from its parameters (pbrt-v2's names and defaults):
//   "string mapping" "uv" (default) | "spherical" | "cylindrical" | "planar";
//   uv: "float uscale" 1, "vscale" 1, "udelta" 0, "vdelta" 0 (lrt's su, sv, du, dv also accepted;
//       the pbrt-v2 name wins when both are given);
//   planar: "vector v1" (1 0 0), "vector v2" (0 1 0), "float udelta" 0, "vdelta" 0;
//   spherical and cylindrical work in texture space, the inverse of textureToWorld (the CTM at
//   the Texture statement); planar projects the world-space point, as pbrt-v2 and v3 do.
#pragma once

#include <memory>

#include "core/paramset.h"
#include "textures/mapping.h"

namespace candela {

// Throws SceneError (at the "mapping" parameter, or loc) for an unknown mapping, listing the known.
std::unique_ptr<TextureMapping2D> createMapping2D(const ParamSet& params,
                                                  const Transform& textureToWorld,
                                                  const FileLoc& loc);

}  // namespace candela
