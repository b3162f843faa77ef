// Name -> shapes. A mesh statement yields one TriangleShape per triangle plus the mesh they share.
#pragma once

#include <memory>
#include <vector>

#include "parser/scene_description.h"
#include "shapes/hyperboloid_normal.h"
#include "shapes/loop_producer.h"
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
// from textures. subdiv picks the code that refines "loopsubdiv" (the same surface either way);
// hyperboloidNormal the hyperboloid's normal (exact, or pbrt's).
CreatedShapes createShapes(const ShapeDesc& desc, const Transform& objectToWorld,
                           TextureFactory& textures, LoopProducer subdiv = LoopProducer::Book,
                           HyperboloidNormal hyperboloidNormal = HyperboloidNormal::Exact);
// Without textures: "alpha" and "shadowalpha" are not read (and so reported unused).
CreatedShapes createShapes(const ShapeDesc& desc, const Transform& objectToWorld,
                           LoopProducer subdiv = LoopProducer::Book,
                           HyperboloidNormal hyperboloidNormal = HyperboloidNormal::Exact);

}  // namespace candela
