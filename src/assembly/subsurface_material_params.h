// "subsurface" and "kdsubsurface" from their statements, with pbrt-v2's parameters and defaults
// (pbrt 2e §16.5):
//   subsurface: name (a measured medium, measured_subsurface.h; none), sigma_a (.0011 .0024 .014),
//     sigma_prime_s (2.55 3.21 3.77) (both: the named medium's when "name" is given), scale 1,
//     index 1.33, Kr 1, bumpmap.
//   kdsubsurface: Kd .5, meanfreepath 1, index 1.33, Kr 1, bumpmap.
// Negative sigma, a non-positive meanfreepath, scale or index and an unknown medium name are
// located errors (texture values are clamped when evaluated).
#pragma once

#include <memory>

#include "assembly/texture_factory.h"
#include "materials/material.h"
#include "parser/scene_description.h"

namespace candela {

// d.name is "subsurface" or "kdsubsurface".
std::unique_ptr<Material> createSubsurfaceMaterial(const MaterialDesc& d, TextureFactory& textures,
                                                   const Texture<Float>* bump);

}  // namespace candela
