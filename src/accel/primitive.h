// A shape with its material and area light: what the aggregates hold and what a hit refers to
// (the lrt draft's GeometricPrimitive, §4.1).
#pragma once

#include "shapes/shape.h"

namespace candela {

class Material;
class AreaLight;
struct MediumInterface;

struct Primitive {
  const Shape* shape = nullptr;
  const Material* material = nullptr;    // nullptr: no scattering (an interface or light only)
  const AreaLight* areaLight = nullptr;  // nullptr: does not emit
  // pbrt-v3's media on the two sides, set only where they differ; nullptr: a ray crossing the
  // surface stays in its medium (always so in scenes without named media).
  const MediumInterface* mediumInterface = nullptr;
};

}  // namespace candela
