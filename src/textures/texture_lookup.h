// The textures a statement's parameters stand for, as the plug-ins that take textures (materials)
// ask for them: a parameter names a texture or gives a constant, and the plug-in only says which
// parameter and its default. The build (assembly/texture_factory.h) implements it, so plug-ins
// need neither the parser nor the factories.
#pragma once

#include <string>

#include "core/spectrum.h"
#include "textures/texture.h"

namespace candela {

class TextureLookup {
 public:
  virtual ~TextureLookup() = default;
  // The texture the parameter names, or a constant of its value (def when absent). Throws
  // SceneError for a texture that does not exist or is of the other type.
  virtual const Texture<Spectrum>* spectrum(const std::string& name, const Spectrum& def) = 0;
  virtual const Texture<Float>* scalar(const std::string& name, Float def) = 0;
};

}  // namespace candela
