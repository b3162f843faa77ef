// A shape with its material and area light: what the aggregates hold and what a hit refers to
// (the lrt draft's GeometricPrimitive, §4.1).
#pragma once

#include "shapes/shape.h"

namespace candela {

class Material;
class AreaLight;

struct Primitive {
  const Shape* shape = nullptr;
  const Material* material = nullptr;    // nullptr: no scattering (an interface or light only)
  const AreaLight* areaLight = nullptr;  // nullptr: does not emit
};

}  // namespace candela
