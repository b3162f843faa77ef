// Everything an aggregate is built over: world-space primitives, and instances of prototypes
// (ObjectBegin/ObjectInstance) under static or animated transforms. A shape with an animated
// transform is an instance of a one-primitive prototype. The RenderJob owns all of it.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "accel/primitive.h"
#include "core/animated_transform.h"

namespace candela {

struct InstancePrototype {
  std::string name;
  std::vector<Primitive> primitives;  // in the prototype's own space
};

struct Instance {
  const InstancePrototype* prototype = nullptr;
  AnimatedTransform instanceToWorld;
};

struct SceneGeometry {
  std::vector<Primitive> primitives;  // static, world space
  std::vector<std::unique_ptr<InstancePrototype>> prototypes;
  std::vector<Instance> instances;
};

}  // namespace candela
