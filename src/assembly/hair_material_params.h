// pbrt-v3's Material "hair" from its statement (pbrt-v3's parameters and defaults):
//   sigma_a (spectrum texture, per unit fibre radius), or color (spectrum texture, the fibres'
//   colour in [0, 1], turned into sigma_a by Chiang et al.'s inversion with beta_n), or eumelanin
//   and pheomelanin (float textures; a missing one is 0); eumelanin 1.3 when none is given;
//   eta 1.55, beta_m .3, beta_n .3, alpha 2 (degrees; all float textures).
// Like pbrt-v3, the first of sigma_a, color and the melanins given wins; the others are not read
// and so reported as unused parameters. Constant values outside the model's domain are located
// errors: negative sigma_a, color outside [0, 1], negative concentrations, eta below 1, beta_m or
// beta_n outside (0, 1]. The material takes no bump map (pbrt-v3's does not).
#pragma once

#include <memory>

#include "assembly/texture_factory.h"
#include "materials/material.h"
#include "parser/scene_description.h"

namespace candela {

std::unique_ptr<Material> createHairMaterial(const MaterialDesc& d, TextureFactory& textures);

}  // namespace candela
