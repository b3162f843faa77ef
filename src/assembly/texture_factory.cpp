#include "assembly/texture_factory.h"

#include <filesystem>
#include <type_traits>

#include "core/scene_path.h"
#include "textures/basic_textures.h"
#include "textures/checkerboard.h"
#include "textures/dots.h"
#include "textures/image_texture.h"
#include "textures/solid_textures.h"
#include "textures/texture_params.h"

namespace candela {

namespace {

constexpr const char* kKnownClasses =
    "bilerp, checkerboard, constant, dots, fbm, imagemap, marble, mix, scale, uv, windy, wrinkled";

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

[[noreturn]] void spectrumOnly(const TextureDesc& d) {
  throw SceneError(d.loc, "texture class '" + d.name + "' makes spectrum textures only, but '" +
                              d.textureName + "' is declared \"float\"");
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

template <typename T>
std::unique_ptr<Texture<T>> TextureFactory::create(const TextureDesc& d, size_t index) {
  const ParamSet& p = d.params;
  const TextureBindings* bindings = d.textures ? &*d.textures : nullptr;
  auto tex = [&](const std::string& name, const T& def) {
    return parameter<T>(p, name, def, d.loc, index, bindings);
  };
  auto mapping2D = [&] { return createMapping2D(p, d.textureToWorld, d.loc); };
  // pbrt-v2 and v3 hand the CTM itself to the 3D mapping as its world-to-texture transform, so a
  // Scale 3 before the Texture statement makes the pattern three times finer; scenes are written
  // for that.
  auto mapping3D = [&] { return TextureMapping3D(d.textureToWorld); };
  const std::string& c = d.name;

  if (c == "constant") return std::make_unique<ConstantTexture<T>>(getOne<T>(p, "value", T(1)));
  if (c == "scale") return std::make_unique<ScaleTexture<T>>(tex("tex1", T(1)), tex("tex2", T(1)));
  if (c == "mix") {
    const Texture<T>* t1 = tex("tex1", T(0));
    const Texture<T>* t2 = tex("tex2", T(1));
    return std::make_unique<MixTexture<T>>(
        t1, t2, parameter<Float>(p, "amount", 0.5f, d.loc, index, bindings));
  }
  if (c == "bilerp")
    return std::make_unique<BilerpTexture<T>>(mapping2D(), getOne<T>(p, "v00", T(0)),
                                              getOne<T>(p, "v01", T(1)), getOne<T>(p, "v10", T(0)),
                                              getOne<T>(p, "v11", T(1)));
  if (c == "uv") {
    if constexpr (std::is_same_v<T, Spectrum>)
      return std::make_unique<UVTexture>(mapping2D());
    else
      spectrumOnly(d);
  }
  if (c == "checkerboard") {
    int dimension = p.getOneInt("dimension", 2);
    if (dimension != 2 && dimension != 3)
      throw SceneError(p.locationOf("dimension", d.loc),
                       "checkerboard dimension must be 2 or 3, not " + std::to_string(dimension));
    std::string aa = p.getOneString("aamode", dimension == 2 ? "closedform" : "supersample");
    if (aa != "closedform" && aa != "supersample" && aa != "none")
      throw SceneError(
          p.locationOf("aamode", d.loc),
          "unknown checkerboard aamode '" + aa + "' (known: closedform, supersample, none)");
    const Texture<T>* t1 = tex("tex1", T(1));
    const Texture<T>* t2 = tex("tex2", T(0));
    if (dimension == 3)
      return std::make_unique<Checkerboard3DTexture<T>>(mapping3D(), t1, t2, aa != "none");
    CheckerboardAA mode = aa == "none"          ? CheckerboardAA::None
                          : aa == "supersample" ? CheckerboardAA::Supersample
                                                : CheckerboardAA::ClosedForm;
    return std::make_unique<Checkerboard2DTexture<T>>(mapping2D(), t1, t2, mode);
  }
  if (c == "dots") {
    // pbrt-v2 and v3 hand "inside" to the dots texture's outside slot and "outside" to its inside
    // (their constructor takes the two in the opposite order to their factory), so in every
    // pbrt scene the "inside" value fills the space between the dots. Files mean what pbrt shows.
    const Texture<T>* between = tex("inside", T(1));
    const Texture<T>* dots = tex("outside", T(0));
    return std::make_unique<DotsTexture<T>>(mapping2D(), between, dots);
  }
  if (c == "fbm")
    return std::make_unique<FBmTexture<T>>(mapping3D(), p.getOneInt("octaves", 8),
                                           p.getOneFloat("roughness", .5f));
  if (c == "wrinkled")
    return std::make_unique<WrinkledTexture<T>>(mapping3D(), p.getOneInt("octaves", 8),
                                                p.getOneFloat("roughness", .5f), clampedOctaves_);
  if (c == "windy") return std::make_unique<WindyTexture<T>>(mapping3D());
  if (c == "marble") {
    if constexpr (std::is_same_v<T, Spectrum>)
      return std::make_unique<MarbleTexture>(
          mapping3D(), p.getOneInt("octaves", 8), p.getOneFloat("roughness", .5f),
          p.getOneFloat("scale", 1), p.getOneFloat("variation", .2f));
    else
      spectrumOnly(d);
  }
  if (c == "imagemap") return createImageTexture<T>(d);
  throw SceneError(d.loc, "unknown texture class '" + c + "' (known: " + kKnownClasses + ")");
}

template <typename T>
std::unique_ptr<Texture<T>> TextureFactory::createImageTexture(const TextureDesc& d) {
  const ParamSet& p = d.params;
  // Every parameter is read before the file, so parameter errors come first.
  std::string filename = p.getOneString("filename", "");
  if (filename.empty())
    throw SceneError(d.loc, "imagemap texture '" + d.textureName + "' needs a \"string filename\"");
  std::string path = resolveScenePath(filename, p.locationOf("filename", d.loc).file);
  std::string colorSpace = p.getOneString("colorspace", "");
  std::string wrapName = p.getOneString("wrap", "repeat");
  std::optional<WrapMode> wrap = parseWrapMode(wrapName);
  if (!wrap)
    throw SceneError(p.locationOf("wrap", d.loc),
                     "unknown wrap mode '" + wrapName + "' (known: repeat, black, clamp)");
  Float maxAnisotropy = p.getOneFloat("maxanisotropy", 8);
  bool trilinear = p.getOneBool("trilinear", false);
  Float scale = p.getOneFloat("scale", 1), gamma = 1;
  // "gamma" is pbrt-v3's bool (true: the numbers are sRGB-encoded, false: linear, whatever the
  // pixel type; absent, pbrt-v3 decodes PNG and TGA only, which the default rule does) or
  // pbrt-v2's float exponent applied after the scale. A "string colorspace" overrides the bool.
  if (const ParamItem* g = p.find("gamma")) {
    if (g->type == ParamType::Bool) {
      bool encoded = p.getOneBool("gamma", false);
      if (colorSpace.empty()) colorSpace = encoded ? kSrgbEncoded : kStoredLinear;
    } else {
      gamma = p.getOneFloat("gamma", 1);
    }
  }
  std::unique_ptr<TextureMapping2D> mapping = createMapping2D(p, d.textureToWorld, d.loc);

  MipKey key{path, colorSpace, *wrap, scale, gamma};
  auto& cache = store<T>().mipmaps;
  std::shared_ptr<const MIPMap<T>> mipmap;
  if (auto it = cache.find(key); it != cache.end()) {
    mipmap = it->second;
  } else {
    const ImageBuffer& img = image(path, colorSpace, d);
    std::vector<T> texels;
    if constexpr (std::is_same_v<T, Float>)
      texels = floatTexels(img, scale, gamma);
    else
      texels = spectrumTexels(img, scale, gamma);
    if (imageOrigin_ == ImageOrigin::BottomLeft) texels = bottomRowFirst(texels, img.width);
    try {
      mipmap = std::make_shared<const MIPMap<T>>(img.width, img.height, std::move(texels), *wrap);
    } catch (const std::invalid_argument& e) {
      throw SceneError(d.loc, "image texture '" + d.textureName + "' (" + path + "): " + e.what());
    }
    cache[key] = mipmap;
    ++mipmapsBuilt_;
  }
  return std::make_unique<ImageTexture<T>>(std::move(mapping), mipmap, trilinear, maxAnisotropy);
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
