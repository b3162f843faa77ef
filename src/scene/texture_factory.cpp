#include "scene/texture_factory.h"

namespace candela {

const TextureDesc* TextureFactory::find(const std::string& textureName,
                                        const std::string& type) const {
  // Later definitions of a name shadow earlier ones, as in pbrt.
  for (auto it = descs_.rbegin(); it != descs_.rend(); ++it)
    if (it->textureName == textureName && it->type == type) return &*it;
  return nullptr;
}

namespace {
[[noreturn]] void unknownClass(const TextureDesc& d) {
  throw SceneError(d.loc, "unknown texture class '" + d.name + "' (known: constant)");
}
}  // namespace

const Texture<Spectrum>* TextureFactory::spectrum(const ParamSet& params, const std::string& name,
                                                  const Spectrum& def, const FileLoc& loc) {
  std::string texName = params.getTexture(name);
  if (texName.empty()) {
    spectrumOwned_.push_back(
        std::make_unique<ConstantTexture<Spectrum>>(params.getOneSpectrum(name, def)));
    return spectrumOwned_.back().get();
  }
  if (auto it = spectrumByName_.find(texName); it != spectrumByName_.end()) return it->second;
  const TextureDesc* d = find(texName, "spectrum");
  if (!d)
    throw SceneError(params.locationOf(name, loc),
                     "no spectrum texture named '" + texName + "' for parameter '" + name + "'");
  if (d->name != "constant") unknownClass(*d);
  spectrumOwned_.push_back(
      std::make_unique<ConstantTexture<Spectrum>>(d->params.getOneSpectrum("value", Spectrum(1))));
  ++created_;
  return spectrumByName_[texName] = spectrumOwned_.back().get();
}

const Texture<Float>* TextureFactory::scalar(const ParamSet& params, const std::string& name,
                                             Float def, const FileLoc& loc) {
  std::string texName = params.getTexture(name);
  if (texName.empty()) {
    floatOwned_.push_back(std::make_unique<ConstantTexture<Float>>(params.getOneFloat(name, def)));
    return floatOwned_.back().get();
  }
  if (auto it = floatByName_.find(texName); it != floatByName_.end()) return it->second;
  const TextureDesc* d = find(texName, "float");
  if (!d)
    throw SceneError(params.locationOf(name, loc),
                     "no float texture named '" + texName + "' for parameter '" + name + "'");
  if (d->name != "constant") unknownClass(*d);
  floatOwned_.push_back(
      std::make_unique<ConstantTexture<Float>>(d->params.getOneFloat("value", 1)));
  ++created_;
  return floatByName_[texName] = floatOwned_.back().get();
}

}  // namespace candela
