// Creates the textures that materials name, once each and only when used (DESIGN.md, data flow
// step 2), and turns a material parameter into a texture: a "texture" reference or a constant.
#pragma once

#include <map>
#include <memory>
#include <vector>

#include "scene/scene_description.h"
#include "textures/texture.h"

namespace candela {

class TextureFactory {
 public:
  explicit TextureFactory(const std::vector<TextureDesc>& descs) : descs_(descs) {}
  // The parameter `name` as a texture: the named texture when the item is a "texture" reference,
  // else a constant of the given value (or def when absent).
  const Texture<Spectrum>* spectrum(const ParamSet& params, const std::string& name,
                                    const Spectrum& def, const FileLoc& loc);
  const Texture<Float>* scalar(const ParamSet& params, const std::string& name, Float def,
                               const FileLoc& loc);
  int texturesCreated() const { return created_; }

 private:
  const TextureDesc* find(const std::string& textureName, const std::string& type) const;
  const std::vector<TextureDesc>& descs_;
  std::map<std::string, const Texture<Spectrum>*> spectrumByName_;
  std::map<std::string, const Texture<Float>*> floatByName_;
  std::vector<std::unique_ptr<Texture<Spectrum>>> spectrumOwned_;
  std::vector<std::unique_ptr<Texture<Float>>> floatOwned_;
  int created_ = 0;
};

}  // namespace candela
