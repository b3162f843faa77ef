// Name -> shapes. A mesh statement yields one TriangleShape per triangle plus the mesh they share.
#pragma once

#include <memory>
#include <vector>

#include "scene/scene_description.h"
#include "shapes/shape.h"

namespace candela {

struct TriangleMesh;

struct CreatedShapes {
  std::vector<std::unique_ptr<Shape>> shapes;
  std::unique_ptr<TriangleMesh> mesh;  // set for trianglemesh and plymesh
  CreatedShapes();
  ~CreatedShapes();
  CreatedShapes(CreatedShapes&&) noexcept;
};

class TextureFactory;

// Triangle meshes' "alpha" and "shadowalpha" (pbrt-v2 cut-outs, float textures or constants) come
// from textures.
CreatedShapes createShapes(const ShapeDesc& desc, const Transform& objectToWorld,
                           TextureFactory& textures);
// Without textures: "alpha" and "shadowalpha" are not read (and so reported unused).
CreatedShapes createShapes(const ShapeDesc& desc, const Transform& objectToWorld);

}  // namespace candela
