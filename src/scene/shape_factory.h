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

CreatedShapes createShapes(const ShapeDesc& desc, const Transform& objectToWorld);

}  // namespace candela
