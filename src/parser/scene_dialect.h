// Which pbrt's scene format a file is written for, where the two give one statement different
// meanings (today: the microfacet models of metal, plastic, substrate, uber, translucent and
// glass). pbrt-v2 and lrt scenes keep pbrt-v2's models; pbrt-v3 scenes get pbrt-v3's.
//
// A scene is pbrt-v3 when it uses a statement only pbrt-v3 has: Integrator (pbrt-v2 has
// SurfaceIntegrator, VolumeIntegrator and Renderer instead), MakeNamedMedium or MediumInterface.
// Otherwise it is pbrt-v2, except that a material giving a parameter only pbrt-v3's version of it
// reads (materialHasPbrtV3Parameters) is made as pbrt-v3's. An explicit choice (--dialect)
// overrides both rules.
#pragma once

#include <optional>
#include <string>

#include "core/compatibility.h"
#include "parser/scene_description.h"

namespace candela {

SceneDialect detectSceneDialect(const SceneDescription& desc);
// "remaproughness" on any of the materials above; "uroughness" or "vroughness" on metal, uber or
// glass (pbrt-v2's substrate has them too).
bool materialHasPbrtV3Parameters(const MaterialDesc& material);
// "pbrt-v2" or "pbrt-v3"; nullopt for anything else.
std::optional<SceneDialect> parseSceneDialect(const std::string& name);

}  // namespace candela
