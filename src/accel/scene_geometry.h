// Everything an aggregate is built over: world-space primitives, and instances of prototypes
// (ObjectBegin/ObjectInstance, lrt draft §4.1.2) under static or animated transforms (pbrt 2e
// §2.9.3). A shape with an animated transform is an instance of a one-shape prototype created in
// its object space. The RenderJob owns all of it; aggregates keep pointers into it, so it must
// outlive them and not change after they are built.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "accel/primitive.h"
#include "core/animated_transform.h"

namespace candela {

// The shapes of one object definition, created once however many instances use it. Its
// primitives are static (one level of instancing: no instances inside a prototype) and have no
// area lights (pbrt ignores them in instances).
struct InstancePrototype {
  std::string name;
  std::vector<Primitive> primitives;  // in the prototype's own space
};

struct Instance {
  const InstancePrototype* prototype = nullptr;  // may have no primitives: then nothing is hit
  AnimatedTransform instanceToWorld;             // isAnimated() tells static from moving
};

struct SceneGeometry {
  std::vector<Primitive> primitives;  // static, world space
  std::vector<std::unique_ptr<InstancePrototype>> prototypes;
  std::vector<Instance> instances;
};

}  // namespace candela
