// pbrt-v3's "disney" material from its statement (materials/disney.h has the model): color (.5),
// metallic (0), eta (1.5), roughness (.5), speculartint (0), anisotropic (0), sheen (0),
// sheentint (.5), clearcoat (0), clearcoatgloss (1), spectrans (0), scatterdistance (0),
// flatness (0), difftrans (1), all textures, the bool thin (false) and bumpmap.
// Constant values outside their ranges are located errors: eta must be positive, difftrans in
// [0, 2], color and scatterdistance non-negative, the others in [0, 1]; colours above 1 and texture
// values are clamped where evaluated. A scatterdistance that may be positive on a solid surface
// asks for subsurface scattering, which is not implemented: warn reports it once, at the
// parameter.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "assembly/texture_factory.h"
#include "materials/material.h"
#include "parser/scene_description.h"

namespace candela {

std::unique_ptr<Material> createDisneyMaterial(
    const MaterialDesc& d, TextureFactory& textures, const Texture<Float>* bump,
    const std::function<void(const FileLoc&, const std::string&)>& warn);

}  // namespace candela
