// The tables of LightSource and AreaLightSource names (issue 34: one home per plug-in): each
// light's dialects, parameters with their defaults and rules, and its create function.
// createLight and createAreaLight (assembly/light_factory.cpp) dispatch through them, and
// unknown-name errors, `candela --list-plugins` and `candela --describe` read them.
#pragma once

#include <memory>
#include <span>

#include "assembly/texture_factory.h"
#include "core/plugin_spec.h"
#include "lights/light.h"
#include "parser/scene_description.h"
#include "shapes/shape.h"

namespace candela {

// A light from its statement; light maps ("mapname") are read through loadImage, and without
// one naming a map is an error. Bad values are SceneErrors at the parameter, or at desc.loc.
using LightCreate = std::unique_ptr<Light> (*)(const LightDesc& desc,
                                               const TextureFactory::ImageLoader& loadImage);

struct LightPlugin {
  PluginSpec spec;
  LightCreate create;
};

std::span<const LightPlugin> lightPlugins();

// The area light the statement attaches to one shape (the shape outlives it).
using AreaLightCreate = std::unique_ptr<AreaLight> (*)(const PluginDesc& desc, const Shape* shape);

struct AreaLightPlugin {
  PluginSpec spec;
  AreaLightCreate create;
};

std::span<const AreaLightPlugin> areaLightPlugins();

}  // namespace candela
