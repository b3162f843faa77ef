// Name -> shapes, through the shapes' table (shapes/shape_plugins.h), whose names the unknown-shape
// error lists. A mesh statement yields one TriangleShape per triangle plus the mesh they share.
#pragma once

#include <memory>
#include <vector>

#include "core/compatibility.h"
#include "parser/scene_description.h"
#include "shapes/shape.h"

namespace candela {

struct TriangleMesh;

struct CreatedShapes {
  std::vector<std::unique_ptr<Shape>> shapes;
  std::unique_ptr<TriangleMesh> mesh;  // set for the meshes: all but the quadrics
  CreatedShapes();
  ~CreatedShapes();
  CreatedShapes(CreatedShapes&&) noexcept;
};

class TextureFactory;

// Triangle meshes' "alpha" and "shadowalpha" (pbrt-v3 cut-outs, float textures or constants) come
// from textures. The profile picks the code that refines "loopsubdiv" (the same surface either
// way) and the hyperboloid's normal (exact, or pbrt's).
CreatedShapes createShapes(const ShapeDesc& desc, const Transform& objectToWorld,
                           TextureFactory& textures, const CompatibilityProfile& profile = {});
// Without textures: "alpha" and "shadowalpha" are not read (and so reported unused).
CreatedShapes createShapes(const ShapeDesc& desc, const Transform& objectToWorld,
                           const CompatibilityProfile& profile = {});

}  // namespace candela
