// The table of lrt's BumpMap statement (lrt draft Appendix C): its height fields ("windy",
// "bumpy"), each scaled by "scale", with their parameters. The material factory
// (assembly/material_factory.cpp) dispatches through it; unknown-name errors, `candela
// --list-plugins` and `candela --describe` read it.
#pragma once

#include <memory>
#include <span>

#include "core/paramset.h"
#include "core/plugin_spec.h"
#include "textures/texture.h"

namespace candela {

struct BumpMapPlugin {
  PluginSpec spec;
  // The scaled height field; bad values are SceneErrors at the parameter, or at loc.
  std::unique_ptr<Texture<Float>> (*create)(const ParamSet& params, const FileLoc& loc);
};

std::span<const BumpMapPlugin> bumpMapPlugins();

}  // namespace candela
