// A set of directions bounded by a cone: every direction within angle acos(cosTheta) of the unit
// axis w (cosTheta = -1: every direction; cosTheta = 1: w alone). The normals of a light's
// surface and the nodes of the light tree are bounded so (pbrt 4e §3.8.4, §12.6).
#pragma once

#include "core/vector.h"

namespace candela {

struct DirectionCone {
  Vector3f w{0, 0, 1};
  Float cosTheta = -1;

  static DirectionCone everyDirection() { return {}; }
  static DirectionCone of(const Vector3f& unitDirection) { return {unitDirection, 1}; }
  bool coversEveryDirection() const { return cosTheta <= -1; }
};

// The smallest cone about an axis in the plane of a.w and b.w that holds both (or every
// direction, when no smaller one does).
DirectionCone unionOf(const DirectionCone& a, const DirectionCone& b);

}  // namespace candela
