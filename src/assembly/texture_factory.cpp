#include "assembly/texture_factory.h"

#include <filesystem>
#include <type_traits>

#include "textures/basic_textures.h"
#include "textures/image_texture.h"
#include "textures/texture_inputs.h"
#include "textures/texture_plugins.h"

namespace candela {

namespace {

template <typename T>
const char* typeName() {
  return std::is_same_v<T, Float> ? "float" : "spectrum";
}

template <typename T>
T getOne(const ParamSet& params, const std::string& name, const T& def) {
  if constexpr (std::is_same_v<T, Float>)
    return params.getOneFloat(name, def);
  else
    return params.getOneSpectrum(name, def);
}

// A class the table has for the other type only.
[[noreturn]] void otherTypeOnly(const TextureDesc& d, const char* made, const char* declared) {
  throw SceneError(d.loc, "texture class '" + d.name + "' makes " + made + " textures only, but '" +
                              d.textureName + "' is declared \"" + declared + "\"");
}

}  // namespace

TextureFactory::TextureFactory(const std::vector<TextureDesc>& descs, ImageLoader loadImage,
                               Warn warn, ImageOrigin imageOrigin, ClampedOctaves clampedOctaves)
    : imageOrigin_(imageOrigin),
      clampedOctaves_(clampedOctaves),
      descs_(descs),
      loadImage_(std::move(loadImage)),
      warn_(std::move(warn)) {}

TextureFactory::~TextureFactory() = default;

template <>
TextureFactory::Store<Spectrum>& TextureFactory::store<Spectrum>() {
  return spectra_;
}
template <>
TextureFactory::Store<Float>& TextureFactory::store<Float>() {
  return floats_;
}

std::optional<size_t> TextureFactory::find(const std::string& textureName, const std::string& type,
                                           size_t visible, const TextureBindings* bindings) const {
  if (bindings) {
    const std::map<std::string, int>& m = type == "float" ? bindings->floats : bindings->spectra;
    auto it = m.find(textureName);
    if (it == m.end() || it->second < 0 || size_t(it->second) >= descs_.size()) return std::nullopt;
    return size_t(it->second);
  }
  for (size_t i = std::min(visible, descs_.size()); i-- > 0;)
    if (descs_[i].textureName == textureName && descs_[i].type == type) return i;
  return std::nullopt;
}

const Texture<Spectrum>* TextureFactory::spectrum(const ParamSet& params, const std::string& name,
                                                  const Spectrum& def, const FileLoc& loc,
                                                  const TextureBindings* bindings) {
  return parameter<Spectrum>(params, name, def, loc, descs_.size(), bindings);
}

const Texture<Float>* TextureFactory::scalar(const ParamSet& params, const std::string& name,
                                             Float def, const FileLoc& loc,
                                             const TextureBindings* bindings) {
  return parameter<Float>(params, name, def, loc, descs_.size(), bindings);
}

template <typename T>
const Texture<T>* TextureFactory::parameter(const ParamSet& params, const std::string& name,
                                            const T& def, const FileLoc& loc, size_t visible,
                                            const TextureBindings* bindings) {
  std::string texName = params.getTexture(name);
  if (texName.empty()) {
    store<T>().owned.push_back(std::make_unique<ConstantTexture<T>>(getOne(params, name, def)));
    return store<T>().owned.back().get();
  }
  if (std::optional<size_t> index = find(texName, typeName<T>(), visible, bindings))
    return named<T>(*index);
  FileLoc where = params.locationOf(name, loc);
  const char* other = std::is_same_v<T, Float> ? "spectrum" : "float";
  if (find(texName, other, visible, bindings))
    throw SceneError(where, "texture '" + texName + "' is a " + other +
                                " texture, but parameter '" + name + "' needs a " + typeName<T>() +
                                " texture");
  std::string before = bindings                  ? " in effect at this statement"
                       : visible < descs_.size() ? " defined before this texture"
                                                 : "";
  throw SceneError(where, std::string("no ") + typeName<T>() + " texture named '" + texName + "'" +
                              before + " for parameter '" + name + "'");
}

template <typename T>
const Texture<T>* TextureFactory::named(size_t index) {
  Store<T>& s = store<T>();
  if (auto it = s.byIndex.find(index); it != s.byIndex.end()) return it->second;
  const TextureDesc& d = descs_[index];
  // Creating and evaluating a texture recurse through the textures it names: a chain deeper than
  // this would overflow a thread's stack (100,000 nested "scale" textures did).
  constexpr int kMaxNesting = 500;
  if (nesting_ >= kMaxNesting)
    throw SceneError(d.loc, std::string("texture '")
                                .append(d.textureName)
                                .append("' is nested more than ")
                                .append(std::to_string(kMaxNesting))
                                .append(" textures deep"));
  ++nesting_;
  std::unique_ptr<Texture<T>> made;
  try {
    made = create<T>(d, index);
  } catch (...) {
    --nesting_;
    throw;
  }
  --nesting_;
  s.owned.push_back(std::move(made));
  ++created_;
  if (warn_)
    d.params.forEachUnused([&](const ParamItem& item) {
      warn_(item.loc, "parameter \"" + item.typeName + " " + item.name + "\" of texture '" +
                          d.textureName + "' was not used");
    });
  return s.byIndex[index] = s.owned.back().get();
}

// One Texture statement as its class's create function reads it.
class TextureFactory::Inputs final : public TextureInputs {
 public:
  Inputs(TextureFactory& factory, const TextureDesc& desc, size_t index)
      : factory_(factory), desc_(desc), index_(index) {}
  const ParamSet& params() const override { return desc_.params; }
  const FileLoc& location() const override { return desc_.loc; }
  const std::string& textureName() const override { return desc_.textureName; }
  const Transform& textureToWorld() const override { return desc_.textureToWorld; }
  ClampedOctaves clampedOctaves() const override { return factory_.clampedOctaves_; }
  // A named texture in effect at the statement (without bindings: defined before this texture).
  const Texture<Spectrum>* spectrum(const std::string& name, const Spectrum& def) override {
    return parameter<Spectrum>(name, def);
  }
  const Texture<Float>* scalar(const std::string& name, Float def) override {
    return parameter<Float>(name, def);
  }
  std::shared_ptr<const MIPMap<Float>> floatMipmap(const std::string& path,
                                                   const std::string& colorSpace, WrapMode wrap,
                                                   Float scale, Float gamma) override {
    return factory_.mipmap<Float>(path, colorSpace, wrap, scale, gamma, desc_);
  }
  std::shared_ptr<const MIPMap<Spectrum>> spectrumMipmap(const std::string& path,
                                                         const std::string& colorSpace,
                                                         WrapMode wrap, Float scale,
                                                         Float gamma) override {
    return factory_.mipmap<Spectrum>(path, colorSpace, wrap, scale, gamma, desc_);
  }

 private:
  template <typename T>
  const Texture<T>* parameter(const std::string& name, const T& def) {
    const TextureBindings* bindings = desc_.textures ? &*desc_.textures : nullptr;
    return factory_.parameter<T>(desc_.params, name, def, desc_.loc, index_, bindings);
  }
  TextureFactory& factory_;
  const TextureDesc& desc_;
  size_t index_;  // of desc_ in the factory's descriptions
};

template <typename T>
std::unique_ptr<Texture<T>> TextureFactory::create(const TextureDesc& d, size_t index) {
  const TexturePlugin& plugin = requirePlugin(texturePlugins(), "texture", d.name, d.loc);
  Inputs inputs(*this, d, index);
  if constexpr (std::is_same_v<T, Float>) {
    if (!plugin.createFloat) otherTypeOnly(d, "spectrum", "float");
    return plugin.createFloat(inputs);
  } else {
    if (!plugin.createSpectrum) otherTypeOnly(d, "float", "spectrum");
    return plugin.createSpectrum(inputs);
  }
}

template <typename T>
std::shared_ptr<const MIPMap<T>> TextureFactory::mipmap(const std::string& path,
                                                        const std::string& colorSpace,
                                                        WrapMode wrap, Float scale, Float gamma,
                                                        const TextureDesc& d) {
  MipKey key{path, colorSpace, wrap, scale, gamma};
  auto& cache = store<T>().mipmaps;
  if (auto it = cache.find(key); it != cache.end()) return it->second;
  const ImageBuffer& img = image(path, colorSpace, d);
  std::vector<T> texels;
  if constexpr (std::is_same_v<T, Float>)
    texels = floatTexels(img, scale, gamma);
  else
    texels = spectrumTexels(img, scale, gamma);
  if (imageOrigin_ == ImageOrigin::BottomLeft) texels = bottomRowFirst(texels, img.width);
  std::shared_ptr<const MIPMap<T>> made;
  try {
    made = std::make_shared<const MIPMap<T>>(img.width, img.height, std::move(texels), wrap);
  } catch (const std::invalid_argument& e) {
    throw SceneError(d.loc, "image texture '" + d.textureName + "' (" + path + "): " + e.what());
  }
  cache[key] = made;
  ++mipmapsBuilt_;
  return made;
}

const ImageBuffer& TextureFactory::image(const std::string& path, const std::string& colorSpace,
                                         const TextureDesc& d) {
  auto key = std::make_pair(path, colorSpace);
  if (auto it = images_.find(key); it != images_.end()) return it->second;
  if (!loadImage_)
    throw SceneError(d.loc, "cannot read image texture '" + d.textureName + "' (" + path +
                                "): no image reader was given");
  ImageBuffer img;
  try {
    img = loadImage_(path, colorSpace);
  } catch (const std::exception& e) {
    std::string message = e.what();
    if (message.find(path) == std::string::npos) message = path + ": " + message;
    throw SceneError(d.loc, "cannot read image texture '" + d.textureName + "': " + message);
  }
  if (!img.consistent())
    throw SceneError(d.loc, "cannot read image texture '" + d.textureName + "': " + path +
                                ": the image reader returned no pixels");
  ++imagesLoaded_;
  return images_[key] = std::move(img);
}

}  // namespace candela
