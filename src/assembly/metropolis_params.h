// The parameters of the Metropolis renderers (see metropolis_params.cpp for each one).
#pragma once

#include <memory>

#include "assembly/plugin_factories.h"

namespace candela {

// pbrt-v3: Integrator "mlt".
std::unique_ptr<Integrator> createMltRenderer(const PluginDesc& integrator,
                                              const WholeImageContext& context);
// pbrt-v2: Renderer "metropolis".
std::unique_ptr<Integrator> createMetropolisIntegrator(const PluginDesc& renderer,
                                                       const WholeImageContext& context);

}  // namespace candela
