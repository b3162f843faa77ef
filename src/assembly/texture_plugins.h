// The texture classes' table (issue 34: one home per plug-in): each class's name, dialects,
// parameters and create functions, one per texture type it makes. TextureFactory dispatches
// through it, and unknown-name errors, `candela --list-plugins` and `candela --describe` read it.
// The create functions live in assembly, not beside the classes in textures/, because they take
// other textures through the TextureFactory.
#pragma once

#include <memory>
#include <span>

#include "assembly/texture_factory.h"
#include "core/plugin_spec.h"

namespace candela {

// What every texture class is made from: the Texture statement and the factory (its textures,
// settings and image cache), through the context. Bad values are SceneErrors at the parameter or
// the statement.
using FloatTextureCreate = std::unique_ptr<Texture<Float>> (*)(TextureFactory::Context& context);
using SpectrumTextureCreate =
    std::unique_ptr<Texture<Spectrum>> (*)(TextureFactory::Context& context);

struct TexturePlugin {
  PluginSpec spec;
  FloatTextureCreate createFloat;        // null: the class makes spectrum textures only
  SpectrumTextureCreate createSpectrum;  // null: float textures only
};

std::span<const TexturePlugin> texturePlugins();

}  // namespace candela
