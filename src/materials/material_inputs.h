// What a material's create function reads its statement through (materials/material_plugins.h):
// the parameters, their textures, the bump map, the dialect's model choice, named materials (for
// mix) and the BSDF files already read. The build implements it (assembly/material_factory.cpp).
#pragma once

#include <memory>
#include <string>

#include "core/error.h"
#include "core/paramset.h"
#include "materials/material.h"
#include "materials/plastic.h"
#include "reflection/fourier_bsdf_table.h"
#include "reflection/irregular_brdf.h"
#include "reflection/merl_brdf.h"
#include "textures/texture_lookup.h"

namespace candela {

class MaterialInputs : public TextureLookup {
 public:
  virtual const ParamSet& params() const = 0;
  virtual const FileLoc& location() const = 0;
  // The statement's bump map ("bumpmap", or lrt's BumpMap statement), or null.
  virtual const Texture<Float>* bumpMap() = 0;
  // Whether the microfacet materials take pbrt-v3's models (parser/scene_dialect.h decides).
  virtual bool pbrtV3Models() const = 0;
  virtual CoatFresnel plasticCoat() const = 0;
  // The named material the string parameter param names (mix); throws SceneError at it.
  virtual const Material* namedMaterial(const std::string& param) = 0;
  // A warning at loc about a parameter the material cannot honour.
  virtual void warn(const FileLoc& loc, const std::string& message) = 0;
  // Tables read from BSDF files, once per path however many materials use them; FileError
  // naming the path when unreadable.
  virtual std::shared_ptr<const MerlBrdfTable> merlTable(const std::string& path) = 0;
  virtual std::shared_ptr<const IrregularBrdfTable> irregularTable(const std::string& path) = 0;
  virtual std::shared_ptr<const FourierBsdfTable> fourierTable(const std::string& path) = 0;

  // The parameter's own location, or the statement's when absent.
  FileLoc locationOf(const std::string& name) const {
    return params().locationOf(name, location());
  }
};

}  // namespace candela
