// MakeNamedMedium "string type" -> Medium: pbrt-v3's "homogeneous" and "heterogeneous" (grid
// density) media with pbrt-v3's parameter names and defaults, in the medium's coordinate system
// (the CTM at the statement). A bad value is a SceneError located at its parameter.
#pragma once

#include <memory>

#include "media/medium.h"
#include "parser/scene_description.h"

namespace candela {

std::unique_ptr<Medium> createNamedMedium(const MediumDesc& desc);

}  // namespace candela
