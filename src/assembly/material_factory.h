// Creates the scene's materials from their statements, once each and only when a shape uses them
// (DESIGN.md, data flow step 2), with pbrt-v2's names, parameters and defaults (lrt draft ch. 10
// where pbrt-v2 lacks the material):
//   matte (Kd .5, sigma 0), plastic (Kd .25, Ks .25, roughness .1), translucent (Kd .25, Ks .25,
//   reflect .5, transmit .5, roughness .1, index 1.5), glass (Kr 1, Kt 1, index 1.5), mirror
//   (Kr .9), metal (eta, k: copper; roughness .01), shinymetal (Ks 1, Kr 1, roughness .1),
//   substrate (Kd .5, Ks .5, uroughness .1, vroughness .1), uber (Kd .25, Ks .25, Kr 0,
//   roughness .1, opacity 1, index 1.5), mix (amount .5, namedmaterial1, namedmaterial2),
//   measured (filename), pbrt-v3's fourier (bsdffile), and lrt's Lafortune fit "clay"; in every
//   dialect pbrt-v3's "disney" (assembly/disney_material_params.h) and "hair"
//   (assembly/hair_material_params.h).
// In a pbrt-v3 scene (parser/scene_dialect.h) metal, plastic, substrate, uber, translucent and
// glass are pbrt-v3's instead: Trowbridge-Reitz microfacets with Smith masking and the parameters
// "remaproughness" (true), metal's and uber's "uroughness"/"vroughness" (default: roughness),
// uber's "Kt" (0), glass's "uroughness"/"vroughness" (0: smooth), and "eta" for "index" on uber and
// glass.
// Every material takes a float texture "bumpmap"; lrt's BumpMap statement ("windy": scale 1,
// stretch 1; "bumpy": octaves 6, omega .5, scale 1) bumps the material in effect.
//
// mix resolves its names through the MakeNamedMaterial definitions in effect at its statement
// (MaterialDesc::namedMaterials; pbrt-v3 scopes them by AttributeBegin/End); a mix that reaches
// itself is an error. measured and fourier files are read once per path (relative to the scene
// file naming them).
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "assembly/texture_factory.h"
#include "materials/material.h"
#include "materials/plastic.h"
#include "parser/scene_description.h"
#include "parser/scene_dialect.h"
#include "reflection/fourier_bsdf_table.h"
#include "reflection/irregular_brdf.h"
#include "reflection/merl_brdf.h"

namespace candela {

// How the factory chooses between the dialects' models.
struct MaterialModelOptions {
  std::optional<SceneDialect> dialect;  // nullopt: detected from the scene and each material
  CoatFresnel plasticCoat = CoatFresnel::Exact;
};

class MaterialFactory {
 public:
  // Called once for each description a material was made from (for unused-parameter reports).
  using Used = std::function<void(const PluginDesc&)>;
  // Receives warnings about parameters a material cannot honour, at their location.
  using Warn = std::function<void(const FileLoc&, const std::string&)>;

  // Materials are appended to *owned; the factory owns textures of BumpMap statements and must
  // live as long as the materials (the render job owns both).
  MaterialFactory(const SceneDescription& desc, TextureFactory& textures,
                  std::vector<std::unique_ptr<Material>>* owned, Used used = {},
                  MaterialModelOptions models = {}, Warn warn = {});
  ~MaterialFactory();
  MaterialFactory(const MaterialFactory&) = delete;
  MaterialFactory& operator=(const MaterialFactory&) = delete;

  // The material of SceneDescription::materials[index]; -1 is the default (matte, Kd .5).
  // Throws SceneError for unknown names, bad parameters or files, and mix cycles.
  const Material* get(int index);

  int tablesLoaded() const { return tablesLoaded_; }  // measured and fourier files read

 private:
  std::unique_ptr<Material> create(const MaterialDesc& d);
  const Material* named(const MaterialDesc& d, const std::string& param);
  const Texture<Float>* bumpMap(const MaterialDesc& d);
  std::unique_ptr<Material> measured(const MaterialDesc& d, const Texture<Float>* bump);
  std::unique_ptr<Material> fourier(const MaterialDesc& d, const Texture<Float>* bump);
  bool usesPbrtV3Models(const MaterialDesc& d) const;
  // pbrt-v3's version of a microfacet material, or null for other names.
  std::unique_ptr<Material> createPbrtV3(const MaterialDesc& d, const Texture<Float>* bump);

  const SceneDescription& desc_;
  TextureFactory& textures_;
  std::vector<std::unique_ptr<Material>>* owned_;
  Used used_;
  Warn warn_;
  MaterialModelOptions models_;
  SceneDialect sceneDialect_;
  std::map<int, const Material*> byIndex_;
  std::set<int> inProgress_;  // mix recursion guard
  std::map<std::string, std::shared_ptr<const MerlBrdfTable>> merl_;
  std::map<std::string, std::shared_ptr<const IrregularBrdfTable>> irregular_;
  std::map<std::string, std::shared_ptr<const FourierBsdfTable>> fourier_;
  std::vector<std::unique_ptr<Texture<Float>>> bumpTextures_;  // from BumpMap statements
  int tablesLoaded_ = 0;
};

}  // namespace candela
