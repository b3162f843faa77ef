// Integrator "sppm" (pbrt-v3): its parameters, checked, and the renderer they make.
#pragma once

#include <memory>

#include "assembly/plugin_factories.h"

namespace candela {

// pbrt-v3's parameters and defaults: "integer numiterations" 64, "integer maxdepth" 5, "integer
// photonsperiteration" -1 (the full image's pixel count), "float radius" 1 (the initial search
// radius, in scene units), "integer imagewritefrequency" (accepted and ignored: the progressive
// passes and --error-log report the image as it converges). --spp replaces numiterations;
// --quick divides it by 16 (pbrt-v3's rule). Bad values are SceneErrors at their location.
std::unique_ptr<Integrator> createSppmIntegrator(const PluginDesc& integrator,
                                                 const WholeImageContext& context);

}  // namespace candela
