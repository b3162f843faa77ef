#include "scene/shape_factory.h"

#include <filesystem>

#include "scene/plugin_factories.h"
#include "shapes/sphere.h"
#include "shapes/triangle_mesh.h"

namespace candela {

CreatedShapes::CreatedShapes() = default;
CreatedShapes::~CreatedShapes() = default;
CreatedShapes::CreatedShapes(CreatedShapes&&) noexcept = default;

CreatedShapes createShapes(const ShapeDesc& desc, const Transform& objectToWorld) {
  CreatedShapes out;
  if (desc.name == "sphere") {
    out.shapes.push_back(createSphereShape(objectToWorld, desc.reverseOrientation, desc.params));
  } else if (desc.name == "trianglemesh") {
    out.shapes = createTriangleMeshShapes(objectToWorld, desc.reverseOrientation, desc.params,
                                          &out.mesh, desc.loc);
  } else if (desc.name == "plymesh") {
    std::string dir = std::filesystem::path(desc.loc.file).parent_path().string();
    out.shapes = createPlyMeshShapes(objectToWorld, desc.reverseOrientation, desc.params, &out.mesh,
                                     desc.loc, dir);
  } else {
    throwUnknownPlugin(desc.loc, "shape", desc.name, {"sphere", "trianglemesh", "plymesh"});
  }
  return out;
}

}  // namespace candela
