// Rendering in another linear colour space (e.g. ACEScg): every colour parameter of the scene is
// converted once, when the scene is built, by the 3x3 matrix from scene_linear RGB (what the
// parser produced) to the working space's RGB; the image then comes out in that space.
#pragma once

#include <array>

#include "parser/scene_description.h"

namespace candela {

using ColorMatrix = std::array<Float, 9>;  // row-major; out = M * rgb

// Returns a copy of desc with every "spectrum"-typed parameter converted by m.
SceneDescription convertColors(const SceneDescription& desc, const ColorMatrix& m);

}  // namespace candela
