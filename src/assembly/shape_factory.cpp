#include "assembly/shape_factory.h"

#include <filesystem>

#include "assembly/plugin_factories.h"
#include "assembly/texture_factory.h"
#include "shapes/cone.h"
#include "shapes/curve_shape.h"
#include "shapes/cylinder.h"
#include "shapes/disk.h"
#include "shapes/heightfield.h"
#include "shapes/hyperboloid.h"
#include "shapes/loop_subdiv_shape.h"
#include "shapes/nurbs.h"
#include "shapes/paraboloid.h"
#include "shapes/sphere.h"
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

}  // namespace

CreatedShapes createShapes(const ShapeDesc& desc, const Transform& objectToWorld,
                           TextureFactory& textures, LoopProducer subdiv,
                           HyperboloidNormal hyperboloidNormal) {
  CreatedShapes out = createShapes(desc, objectToWorld, subdiv, hyperboloidNormal);
  if (out.mesh && (desc.name == "trianglemesh" || desc.name == "plymesh"))
    readAlpha(desc, textures, out.mesh.get());
  return out;
}

CreatedShapes createShapes(const ShapeDesc& desc, const Transform& objectToWorld,
                           LoopProducer subdiv, HyperboloidNormal hyperboloidNormal) {
  CreatedShapes out;
  using QuadricFactory = std::unique_ptr<Shape> (*)(const Transform&, bool, const ParamSet&);
  QuadricFactory quadric = nullptr;
  if (desc.name == "sphere") quadric = createSphereShape;
  if (desc.name == "cylinder") quadric = createCylinderShape;
  if (desc.name == "disk") quadric = createDiskShape;
  if (desc.name == "cone") quadric = createConeShape;
  if (desc.name == "paraboloid") quadric = createParaboloidShape;
  if (desc.name == "hyperboloid") {
    out.shapes.push_back(createHyperboloidShape(objectToWorld, desc.reverseOrientation, desc.params,
                                                hyperboloidNormal));
  } else if (quadric) {
    out.shapes.push_back(quadric(objectToWorld, desc.reverseOrientation, desc.params));
  } else if (desc.name == "heightfield") {
    out.shapes = createHeightfieldShapes(objectToWorld, desc.reverseOrientation, desc.params,
                                         &out.mesh, desc.loc);
  } else if (desc.name == "trianglemesh") {
    out.shapes = createTriangleMeshShapes(objectToWorld, desc.reverseOrientation, desc.params,
                                          &out.mesh, desc.loc);
  } else if (desc.name == "loopsubdiv") {
    out.shapes = createLoopSubdivShapes(objectToWorld, desc.reverseOrientation, desc.params,
                                        &out.mesh, desc.loc, subdiv);
  } else if (desc.name == "nurbs") {
    out.shapes =
        createNurbsShapes(objectToWorld, desc.reverseOrientation, desc.params, &out.mesh, desc.loc);
  } else if (desc.name == "curve") {
    out.shapes = createCurveShapes(objectToWorld, desc.reverseOrientation, desc.params, desc.loc);
  } else if (desc.name == "plymesh") {
    std::string dir = std::filesystem::path(desc.loc.file).parent_path().string();
    out.shapes = createPlyMeshShapes(objectToWorld, desc.reverseOrientation, desc.params, &out.mesh,
                                     desc.loc, dir);
  } else {
    throwUnknownPlugin(desc.loc, "shape", desc.name,
                       {"sphere", "cylinder", "disk", "cone", "paraboloid", "hyperboloid",
                        "heightfield", "trianglemesh", "plymesh", "loopsubdiv", "nurbs", "curve"});
  }
  return out;
}

}  // namespace candela
