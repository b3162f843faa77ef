// The tables of LightSource and AreaLightSource names (issue 34: one home per plug-in): each
// light's dialects, parameters with their defaults and rules, and its create function.
// The build (assembly/light_factory.cpp) dispatches through them, and unknown-name errors, `candela
// --list-plugins` and `candela --describe` read them.
#pragma once

#include <memory>
#include <span>

#include "core/image_loader.h"
#include "core/paramset.h"
#include "core/plugin_spec.h"
#include "core/transform.h"
#include "lights/light.h"
#include "shapes/shape.h"

namespace candela {

// A LightSource statement: its parameters and location, the CTM there, and how to read light
// maps ("mapname"; without a loader naming a map is an error).
struct LightInputs {
  const ParamSet& params;
  const FileLoc& loc;
  const Transform& lightToWorld;
  const ImageLoader& loadImage;
};

// Bad values are SceneErrors at the parameter, or at in.loc.
using LightCreate = std::unique_ptr<Light> (*)(const LightInputs& in);

struct LightPlugin {
  PluginSpec spec;
  LightCreate create;
};

std::span<const LightPlugin> lightPlugins();

// The area light the statement attaches to one shape (the shape outlives it).
using AreaLightCreate = std::unique_ptr<AreaLight> (*)(const ParamSet& params, const FileLoc& loc,
                                                       const Shape* shape);

struct AreaLightPlugin {
  PluginSpec spec;
  AreaLightCreate create;
};

std::span<const AreaLightPlugin> areaLightPlugins();

}  // namespace candela
