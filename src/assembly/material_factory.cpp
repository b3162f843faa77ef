// Creates the scene's materials from their statements through the table of
// materials/material_plugins.h, once each and only when a shape uses them.
#include "assembly/material_factory.h"

#include <filesystem>

#include "assembly/plugin_factories.h"
#include "materials/lafortune_material.h"
#include "materials/material_plugins.h"
#include "materials/matte.h"
#include "materials/measured.h"
#include "parser/spectrum_input.h"
#include "textures/bump_map_plugins.h"

namespace candela {

// One material statement as its create function sees it.
class MaterialFactory::StatementInputs : public MaterialInputs {
 public:
  StatementInputs(MaterialFactory& factory, const MaterialDesc& d) : f_(factory), d_(d) {}
  const ParamSet& params() const override { return d_.params; }
  const FileLoc& location() const override { return d_.loc; }
  const Texture<Spectrum>* spectrum(const std::string& name, const Spectrum& def) override {
    return f_.textures_.spectrum(d_, name, def);
  }
  const Texture<Float>* scalar(const std::string& name, Float def) override {
    return f_.textures_.scalar(d_, name, def);
  }
  const Texture<Float>* bumpMap() override {
    if (!bumpRead_) bump_ = f_.bumpMap(d_);
    bumpRead_ = true;
    return bump_;
  }
  bool pbrtV3Models() const override { return f_.usesPbrtV3Models(d_); }
  CoatFresnel plasticCoat() const override { return f_.models_.plasticCoat; }
  const Material* namedMaterial(const std::string& param) override { return f_.named(d_, param); }
  void warn(const FileLoc& loc, const std::string& message) override {
    if (f_.warn_) f_.warn_(loc, message);
  }
  std::shared_ptr<const MerlBrdfTable> merlTable(const std::string& path) override {
    auto& t = f_.merl_[path];
    if (!t) {
      ++f_.tablesLoaded_;
      t = std::make_shared<const MerlBrdfTable>(readMerlBrdf(path));
    }
    return t;
  }
  std::shared_ptr<const IrregularBrdfTable> irregularTable(const std::string& path) override {
    auto& t = f_.irregular_[path];
    if (!t) {
      ++f_.tablesLoaded_;
      auto toRGB = [](std::span<const Float> lambda, std::span<const Float> values) {
        std::vector<SpectrumSample> s;
        for (size_t i = 0; i < lambda.size() && i < values.size(); ++i)
          s.push_back({lambda[i], values[i]});
        return spectrumSamplesToRGB(std::move(s), SpectrumUse::Reflectance);
      };
      t = std::make_shared<const IrregularBrdfTable>(readIrregularBrdf(path, toRGB));
    }
    return t;
  }
  std::shared_ptr<const FourierBsdfTable> fourierTable(const std::string& path) override {
    auto& t = f_.fourier_[path];
    if (!t) {
      ++f_.tablesLoaded_;
      t = std::make_shared<const FourierBsdfTable>(readFourierBsdf(path));
    }
    return t;
  }

 private:
  MaterialFactory& f_;
  const MaterialDesc& d_;
  const Texture<Float>* bump_ = nullptr;
  bool bumpRead_ = false;
};

MaterialFactory::MaterialFactory(const SceneDescription& desc, TextureFactory& textures,
                                 std::vector<std::unique_ptr<Material>>* owned, Used used,
                                 CompatibilityProfile models, Warn warn)
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
  if (b.name == "imagemap")
    throw SceneError(b.loc,
                     "BumpMap \"imagemap\" is not supported; define a float imagemap Texture and "
                     "give the material \"texture bumpmap\"");
  const BumpMapPlugin& plugin = requirePlugin(bumpMapPlugins(), "bump map", b.name, b.loc);
  bumpTextures_.push_back(plugin.create(b.params, b.loc));
  return bumpTextures_.back().get();
}

std::unique_ptr<Material> MaterialFactory::create(const MaterialDesc& d) {
  if (isUnprintedLafortuneFit(d.name))
    throw SceneError(d.loc, "material '" + d.name +
                                "' is one of lrt's measured Lafortune fits whose coefficients the "
                                "book does not print; only \"clay\" is available");
  const MaterialPlugin& plugin = requirePlugin(materialPlugins(), "material", d.name, d.loc);
  StatementInputs inputs(*this, d);
  return plugin.create(inputs);
}

std::unique_ptr<Material> createDefaultMaterial(TextureFactory& textures) {
  return std::make_unique<MatteMaterial>(textures.spectrum({}, "Kd", Spectrum(0.5f), FileLoc()),
                                         textures.scalar({}, "sigma", 0, FileLoc()));
}

}  // namespace candela
