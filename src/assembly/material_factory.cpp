// Material "name" -> Material (lrt draft ch. 10; pbrt-v2's parameter names and defaults).
#include "assembly/material_factory.h"

#include <filesystem>

#include "assembly/disney_material_params.h"
#include "assembly/hair_material_params.h"
#include "assembly/plugin_factories.h"
#include "assembly/subsurface_material_params.h"
#include "core/scene_path.h"
#include "materials/fourier.h"
#include "materials/glass.h"
#include "materials/lafortune_material.h"
#include "materials/matte.h"
#include "materials/measured.h"
#include "materials/metal.h"
#include "materials/mirror.h"
#include "materials/mix.h"
#include "materials/plastic.h"
#include "materials/shinymetal.h"
#include "materials/substrate.h"
#include "materials/translucent.h"
#include "materials/uber.h"
#include "parser/spectrum_input.h"
#include "textures/solid_textures.h"

namespace candela {

namespace {

const std::vector<std::string> kMaterialNames = {
    "matte",      "plastic",      "translucent", "glass",  "mirror",   "metal",
    "shinymetal", "substrate",    "uber",        "mix",    "measured", "clay",
    "subsurface", "kdsubsurface", "fourier",     "disney", "hair"};
// Named in the draft (§10.9) without coefficients.
const std::set<std::string> kUnprintedFits = {"felt", "primer", "skin", "bluepaint",
                                              "brushedmetal"};

// Height fields of lrt's BumpMap statement (lrt draft Appendix C), scaled by "scale".
class ScaledFloatTexture : public Texture<Float> {
 public:
  ScaledFloatTexture(std::unique_ptr<Texture<Float>> t, Float s) : t_(std::move(t)), s_(s) {}
  Float evaluate(const SurfaceInteraction& si) const override { return s_ * t_->evaluate(si); }

 private:
  std::unique_ptr<Texture<Float>> t_;
  Float s_;
};

}  // namespace

MaterialFactory::MaterialFactory(const SceneDescription& desc, TextureFactory& textures,
                                 std::vector<std::unique_ptr<Material>>* owned, Used used,
                                 MaterialModelOptions models, Warn warn)
    : desc_(desc),
      textures_(textures),
      owned_(owned),
      used_(std::move(used)),
      warn_(std::move(warn)),
      models_(models),
      sceneDialect_(models.dialect.value_or(detectSceneDialect(desc))) {}

bool MaterialFactory::usesPbrtV3Models(const MaterialDesc& d) const {
  if (models_.dialect) return *models_.dialect == SceneDialect::PbrtV3;
  return sceneDialect_ == SceneDialect::PbrtV3 || materialHasPbrtV3Parameters(d);
}

std::unique_ptr<Material> MaterialFactory::createPbrtV3(const MaterialDesc& d,
                                                        const Texture<Float>* bump) {
  const ParamSet& p = d.params;
  const FileLoc& loc = d.loc;
  auto spec = [&](const char* name, Float def) {
    return textures_.spectrum(p, name, Spectrum(def), loc);
  };
  auto flt = [&](const char* name, Float def) { return textures_.scalar(p, name, def, loc); };
  // A texture only when the parameter is given, so that unused defaults are not looked up.
  auto given = [&](const char* name) { return p.find(name) ? flt(name, 0) : nullptr; };
  TrowbridgeReitzRoughness r;
  r.remap = p.getOneBool("remaproughness", true);
  // pbrt-v3 reads "eta" and, without it, "index".
  auto index = [&] { return p.find("eta") ? flt("eta", 1.5f) : flt("index", 1.5f); };
  if (d.name == "metal") {
    const Texture<Float>*u = given("uroughness"), *v = given("vroughness");
    const Texture<Float>* rough = !u || !v ? flt("roughness", 0.01f) : nullptr;
    r.u = u ? u : rough;
    r.v = v ? v : rough;
    return std::make_unique<MetalMaterial>(textures_.spectrum(p, "eta", copper::kEta, loc),
                                           textures_.spectrum(p, "k", copper::kK, loc), r, bump);
  }
  if (d.name == "plastic") {
    r.u = r.v = flt("roughness", 0.1f);
    return std::make_unique<PlasticMaterial>(spec("Kd", 0.25f), spec("Ks", 0.25f), r, bump,
                                             models_.plasticCoat);
  }
  if (d.name == "substrate") {
    r.u = flt("uroughness", 0.1f);
    r.v = flt("vroughness", 0.1f);
    return std::make_unique<SubstrateMaterial>(spec("Kd", 0.5f), spec("Ks", 0.5f), r, bump);
  }
  if (d.name == "uber") {
    // v falls back to u here, to roughness in metal: pbrt-v3 differs between the two.
    r.u = given("uroughness");
    if (!r.u) r.u = flt("roughness", 0.1f);
    r.v = given("vroughness");
    if (!r.v) r.v = r.u;
    UberMaterial::Textures t{spec("Kd", 0.25f),  spec("Ks", 0.25f), spec("Kr", 0),
                             spec("opacity", 1), nullptr,           index(),
                             spec("Kt", 0)};
    return std::make_unique<UberMaterial>(t, r, bump);
  }
  if (d.name == "translucent") {
    r.u = r.v = flt("roughness", 0.1f);
    return std::make_unique<TranslucentMaterial>(spec("Kd", 0.25f), spec("Ks", 0.25f),
                                                 spec("reflect", 0.5f), spec("transmit", 0.5f), r,
                                                 p.getOneFloat("index", 1.5f), bump);
  }
  if (d.name == "glass") {
    r.u = flt("uroughness", 0);
    r.v = flt("vroughness", 0);
    return std::make_unique<GlassMaterial>(spec("Kr", 1), spec("Kt", 1), index(), r, bump);
  }
  return nullptr;
}

MaterialFactory::~MaterialFactory() = default;

const Material* MaterialFactory::get(int index) {
  if (auto it = byIndex_.find(index); it != byIndex_.end()) return it->second;
  std::unique_ptr<Material> m;
  if (index < 0) {
    m = createDefaultMaterial(textures_);
  } else {
    const MaterialDesc& md = desc_.materials.at(size_t(index));
    // pbrt-v3: Material "" or "none" is no material; a shape with it only bounds media.
    if (md.name.empty() || md.name == "none") return byIndex_[index] = nullptr;
    if (!inProgress_.insert(index).second)
      throw SceneError(md.loc, "material '" + md.name + "' mixes itself (a mix cycle)");
    m = create(md);
    inProgress_.erase(index);
    if (used_) {
      used_(md);
      if (md.bumpMap) used_(*md.bumpMap);
    }
  }
  owned_->push_back(std::move(m));
  return byIndex_[index] = owned_->back().get();
}

const Material* MaterialFactory::named(const MaterialDesc& d, const std::string& param) {
  std::string name = d.params.getOneString(param, "");
  FileLoc loc = d.params.locationOf(param, d.loc);
  if (name.empty()) throw SceneError(loc, "mix needs \"string " + param + "\"");
  // Named materials are graphics state: the mix sees those in effect at its statement.
  const std::map<std::string, int>& known =
      d.namedMaterials ? *d.namedMaterials : desc_.namedMaterials;
  auto it = known.find(name);
  if (it == known.end()) throw SceneError(loc, "mix: unknown named material '" + name + "'");
  const Material* m = get(it->second);
  if (!m) throw SceneError(loc, "mix: named material '" + name + "' is \"none\"");
  return m;
}

const Texture<Float>* MaterialFactory::bumpMap(const MaterialDesc& d) {
  if (d.params.find("bumpmap")) return textures_.scalar(d, "bumpmap", 0);
  if (!d.bumpMap) return nullptr;
  const PluginDesc& b = *d.bumpMap;
  Float s = b.params.getOneFloat("scale", 1);
  std::unique_ptr<Texture<Float>> t;
  if (b.name == "windy") {
    Float stretch = b.params.getOneFloat("stretch", 1);
    if (stretch <= 0) throw SceneError(b.loc, "windy: \"stretch\" must be positive");
    t = std::make_unique<WindyTexture<Float>>(TextureMapping3D(scale(stretch, stretch, stretch)));
  } else if (b.name == "bumpy") {
    t = std::make_unique<FBmTexture<Float>>(TextureMapping3D(Transform()),
                                            b.params.getOneInt("octaves", 6),
                                            b.params.getOneFloat("omega", 0.5f));
  } else if (b.name == "imagemap") {
    throw SceneError(b.loc,
                     "BumpMap \"imagemap\" is not supported; define a float imagemap Texture and "
                     "give the material \"texture bumpmap\"");
  } else {
    throwUnknownPlugin(b.loc, "bump map", b.name, {"windy", "bumpy"});
  }
  bumpTextures_.push_back(std::make_unique<ScaledFloatTexture>(std::move(t), s));
  return bumpTextures_.back().get();
}

std::unique_ptr<Material> MaterialFactory::measured(const MaterialDesc& d,
                                                    const Texture<Float>* bump) {
  std::string filename = d.params.getOneString("filename", "");
  if (filename.empty()) throw SceneError(d.loc, "measured needs \"string filename\"");
  FileLoc loc = d.params.locationOf("filename", d.loc);
  std::string path = resolveScenePath(filename, loc.file);
  try {
    if (auto it = merl_.find(path); it != merl_.end())
      return std::make_unique<MeasuredMaterial>(it->second, bump);
    if (auto it = irregular_.find(path); it != irregular_.end())
      return std::make_unique<MeasuredMaterial>(it->second, bump);
    ++tablesLoaded_;
    if (isMerlBrdfFile(path)) {
      auto t = std::make_shared<const MerlBrdfTable>(readMerlBrdf(path));
      merl_[path] = t;
      return std::make_unique<MeasuredMaterial>(t, bump);
    }
    auto toRGB = [](std::span<const Float> lambda, std::span<const Float> values) {
      std::vector<SpectrumSample> s;
      for (size_t i = 0; i < lambda.size() && i < values.size(); ++i)
        s.push_back({lambda[i], values[i]});
      return spectrumSamplesToRGB(std::move(s), SpectrumUse::Reflectance);
    };
    auto t = std::make_shared<const IrregularBrdfTable>(readIrregularBrdf(path, toRGB));
    irregular_[path] = t;
    return std::make_unique<MeasuredMaterial>(t, bump);
  } catch (const FileError& e) {
    throw SceneError(loc, e.what());
  }
}

std::unique_ptr<Material> MaterialFactory::fourier(const MaterialDesc& d,
                                                   const Texture<Float>* bump) {
  std::string filename = d.params.getOneString("bsdffile", "");
  FileLoc loc = d.params.locationOf("bsdffile", d.loc);
  if (filename.empty()) throw SceneError(loc, "fourier needs \"string bsdffile\"");
  std::string path = resolveScenePath(filename, loc.file);
  if (auto it = fourier_.find(path); it != fourier_.end())
    return std::make_unique<FourierMaterial>(it->second, bump);
  try {
    ++tablesLoaded_;
    auto t = std::make_shared<const FourierBsdfTable>(readFourierBsdf(path));
    fourier_[path] = t;
    return std::make_unique<FourierMaterial>(t, bump);
  } catch (const FileError& e) {
    throw SceneError(loc, e.what());
  }
}

std::unique_ptr<Material> MaterialFactory::create(const MaterialDesc& d) {
  const ParamSet& p = d.params;
  const FileLoc& loc = d.loc;
  auto spec = [&](const char* name, Float def) {
    return textures_.spectrum(d, name, Spectrum(def));
  };
  auto flt = [&](const char* name, Float def) { return textures_.scalar(d, name, def); };
  if (d.name == "mix") {
    const Material* m1 = named(d, "namedmaterial1");
    const Material* m2 = named(d, "namedmaterial2");
    return std::make_unique<MixMaterial>(m1, m2, spec("amount", 0.5f));
  }
  // pbrt-v3's hair, in every dialect (no other has the name); it takes no bump map.
  if (d.name == "hair") return createHairMaterial(d, textures_);
  const Texture<Float>* bump = bumpMap(d);
  // pbrt-v3's only; no other dialect has a material of that name.
  if (d.name == "disney") return createDisneyMaterial(d, textures_, bump, warn_);
  if (usesPbrtV3Models(d))
    if (auto m = createPbrtV3(d, bump)) return m;
  if (d.name == "matte")
    return std::make_unique<MatteMaterial>(spec("Kd", 0.5f), flt("sigma", 0), bump);
  if (d.name == "plastic")
    return std::make_unique<PlasticMaterial>(spec("Kd", 0.25f), spec("Ks", 0.25f),
                                             flt("roughness", 0.1f), bump, models_.plasticCoat);
  if (d.name == "translucent")
    return std::make_unique<TranslucentMaterial>(
        spec("Kd", 0.25f), spec("Ks", 0.25f), spec("reflect", 0.5f), spec("transmit", 0.5f),
        flt("roughness", 0.1f), p.getOneFloat("index", 1.5f), bump);
  if (d.name == "glass")
    return std::make_unique<GlassMaterial>(spec("Kr", 1), spec("Kt", 1), flt("index", 1.5f), bump);
  if (d.name == "mirror") return std::make_unique<MirrorMaterial>(spec("Kr", 0.9f), bump);
  if (d.name == "metal")
    return std::make_unique<MetalMaterial>(textures_.spectrum(d, "eta", copper::kEta),
                                           textures_.spectrum(d, "k", copper::kK),
                                           flt("roughness", 0.01f), bump);
  if (d.name == "shinymetal")
    return std::make_unique<ShinyMetalMaterial>(spec("Ks", 1), spec("Kr", 1),
                                                flt("roughness", 0.1f), bump);
  if (d.name == "substrate")
    return std::make_unique<SubstrateMaterial>(
        spec("Kd", 0.5f), spec("Ks", 0.5f), flt("uroughness", 0.1f), flt("vroughness", 0.1f), bump);
  if (d.name == "uber")
    return std::make_unique<UberMaterial>(
        UberMaterial::Textures{spec("Kd", 0.25f), spec("Ks", 0.25f), spec("Kr", 0),
                               spec("opacity", 1), flt("roughness", 0.1f), flt("index", 1.5f)},
        bump);
  if (d.name == "measured") return measured(d, bump);
  if (d.name == "fourier") return fourier(d, bump);
  // The dipole's translucent materials (pbrt 2e §16.5): subsurface_material_params.h.
  if (d.name == "subsurface" || d.name == "kdsubsurface")
    return createSubsurfaceMaterial(d, textures_, bump);
  if (auto fit = lafortuneFit(d.name)) return std::make_unique<LafortuneMaterial>(*fit, bump);
  if (kUnprintedFits.count(d.name))
    throw SceneError(loc, "material '" + d.name +
                              "' is one of lrt's measured Lafortune fits whose coefficients the "
                              "book does not print; only \"clay\" is available");
  throwUnknownPlugin(loc, "material", d.name, kMaterialNames);
}

std::unique_ptr<Material> createDefaultMaterial(TextureFactory& textures) {
  return std::make_unique<MatteMaterial>(textures.spectrum({}, "Kd", Spectrum(0.5f), FileLoc()),
                                         textures.scalar({}, "sigma", 0, FileLoc()));
}

}  // namespace candela
