#include "assembly/shape_factory.h"

#include <filesystem>

#include "assembly/texture_factory.h"
#include "core/plugin_spec.h"
#include "shapes/shape_plugins.h"
#include "shapes/triangle_mesh.h"

namespace candela {

CreatedShapes::CreatedShapes() = default;
CreatedShapes::~CreatedShapes() = default;
CreatedShapes::CreatedShapes(CreatedShapes&&) noexcept = default;

namespace {

// Zero where either texture is zero, else one: a cut-out for shadow rays.
class EitherZeroTexture : public Texture<Float> {
 public:
  EitherZeroTexture(const Texture<Float>* a, const Texture<Float>* b) : a_(a), b_(b) {}
  Float evaluate(const SurfaceInteraction& si) const override {
    return a_->evaluate(si) == 0 || b_->evaluate(si) == 0 ? 0 : 1;
  }

 private:
  const Texture<Float>* a_;
  const Texture<Float>* b_;
};

// Cut-outs: "alpha" (a float texture or constant; 1, opaque, needs no test) removes hits where it
// is 0 for every ray; pbrt-v3's "shadowalpha" removes more for shadow rays only, which pass where
// either is 0 (pbrt-v3 Triangle::IntersectP tests both; pbrt-v2 had alpha alone).
void readAlpha(const ShapeDesc& desc, TextureFactory& textures, TriangleMesh* mesh) {
  auto read = [&](const char* name) -> const Texture<Float>* {
    if (desc.params.getTexture(name).empty() && desc.params.getOneFloat(name, 1) == 1)
      return nullptr;
    return textures.scalar(desc, name, 1);
  };
  mesh->alpha = read("alpha");
  const Texture<Float>* shadow = read("shadowalpha");
  if (mesh->alpha && shadow)
    mesh->shadowAlpha =
        textures.adopt<Float>(std::make_unique<EitherZeroTexture>(mesh->alpha, shadow));
  else
    mesh->shadowAlpha = shadow ? shadow : mesh->alpha;
}

// The shapes whose table entry declares "alpha" (the triangle meshes) take cut-outs.
bool declaresAlpha(const PluginSpec& spec) {
  for (const ParamSpec& p : spec.params)
    if (p.name == "alpha") return true;
  return false;
}

const ShapePlugin& requireShape(const ShapeDesc& desc) {
  return requirePlugin(shapePlugins(), "shape", desc.name, desc.loc);
}

CreatedShapes create(const ShapePlugin& plugin, const ShapeDesc& desc,
                     const Transform& objectToWorld, LoopProducer subdiv,
                     HyperboloidNormal hyperboloidNormal) {
  std::string dir = std::filesystem::path(desc.loc.file).parent_path().string();
  ShapeInputs in{.objectToWorld = objectToWorld,
                 .reverseOrientation = desc.reverseOrientation,
                 .params = desc.params,
                 .loc = desc.loc,
                 .directory = dir,
                 .subdiv = subdiv,
                 .hyperboloidNormal = hyperboloidNormal};
  CreatedShapes out;
  out.shapes = plugin.create(in, &out.mesh);
  return out;
}

}  // namespace

CreatedShapes createShapes(const ShapeDesc& desc, const Transform& objectToWorld,
                           TextureFactory& textures, const CompatibilityProfile& profile) {
  const ShapePlugin& plugin = requireShape(desc);
  CreatedShapes out =
      create(plugin, desc, objectToWorld, profile.subdiv, profile.hyperboloidNormal);
  if (out.mesh && declaresAlpha(plugin.spec)) readAlpha(desc, textures, out.mesh.get());
  return out;
}

CreatedShapes createShapes(const ShapeDesc& desc, const Transform& objectToWorld,
                           const CompatibilityProfile& profile) {
  return create(requireShape(desc), desc, objectToWorld, profile.subdiv, profile.hyperboloidNormal);
}

}  // namespace candela
