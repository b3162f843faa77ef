// The texture classes' table (issue 34: one home per plug-in): each class's name, dialects,
// parameters and create functions, one per texture type it makes. TextureFactory dispatches
// through it, and unknown-name errors, `candela --list-plugins` and `candela --describe` read it.
#pragma once

#include <memory>
#include <span>

#include "core/plugin_spec.h"
#include "textures/texture_inputs.h"

namespace candela {

// What every texture class is made from: the Texture statement, the textures it names and the
// images it reads (textures/texture_inputs.h). Bad values are SceneErrors at the parameter or the
// statement.
using FloatTextureCreate = std::unique_ptr<Texture<Float>> (*)(TextureInputs& in);
using SpectrumTextureCreate = std::unique_ptr<Texture<Spectrum>> (*)(TextureInputs& in);

struct TexturePlugin {
  PluginSpec spec;
  FloatTextureCreate createFloat;        // null: the class makes spectrum textures only
  SpectrumTextureCreate createSpectrum;  // null: float textures only
};

std::span<const TexturePlugin> texturePlugins();

}  // namespace candela
