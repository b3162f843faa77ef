// The parameters of the Metropolis renderers (see metropolis_params.cpp for each one).
#pragma once

#include <memory>

#include "assembly/plugin_factories.h"

namespace candela {

// pbrt-v3: Integrator "mlt".
std::unique_ptr<ImageRenderer> createMltRenderer(const PluginDesc& integrator,
                                                 const ImageRendererContext& context);
// pbrt-v2: Renderer "metropolis".
std::unique_ptr<ImageRenderer> createMetropolisRenderer(const PluginDesc& renderer,
                                                        const ImageRendererContext& context);

}  // namespace candela
