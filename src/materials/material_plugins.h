// The table of Material statement names: each material's parameters, defaults and rules, and the
// create function beside its class. The build dispatches through it (assembly/material_factory.cpp)
// and `candela --list-plugins material` / `--describe NAME` print it.
#pragma once

#include <memory>
#include <span>

#include "core/plugin_spec.h"
#include "materials/material.h"
#include "materials/material_inputs.h"

namespace candela {

struct MaterialPlugin {
  PluginSpec spec;
  std::unique_ptr<Material> (*create)(MaterialInputs& in);
};

std::span<const MaterialPlugin> materialPlugins();

}  // namespace candela
