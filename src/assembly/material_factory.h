// Creates the scene's materials from their statements, once each and only when a shape uses them
// (docs/architecture.md, data flow step 2), through the table of materials/material_plugins.h
// (names, parameters, defaults and rules: `candela --list-plugins material`, `--describe NAME`).
// In a pbrt-v3 scene (parser/scene_dialect.h) metal, plastic, substrate, uber, translucent and
// glass take pbrt-v3's microfacet models; lrt's BumpMap statement (textures/bump_map_plugins.h)
// bumps the material in effect, a "bumpmap" float texture the material that names it.
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
#include <span>
#include <string>
#include <vector>

#include "assembly/texture_factory.h"
#include "core/plugin_spec.h"
#include "materials/material.h"
#include "materials/plastic.h"
#include "parser/scene_description.h"
#include "parser/scene_dialect.h"
#include "reflection/fourier_bsdf_table.h"
#include "reflection/irregular_brdf.h"
#include "reflection/merl_brdf.h"

namespace candela {

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
                  CompatibilityProfile models = {}, Warn warn = {});
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
  bool usesPbrtV3Models(const MaterialDesc& d) const;
  class StatementInputs;

  const SceneDescription& desc_;
  TextureFactory& textures_;
  std::vector<std::unique_ptr<Material>>* owned_;
  Used used_;
  Warn warn_;
  CompatibilityProfile models_;
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
