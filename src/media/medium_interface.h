// pbrt-v3's MediumInterface (pbrt 3e §11.3.1): the media on the two sides of a surface. "Inside"
// is the side the geometric normal points away from, "outside" the side it points into. A
// primitive holds one only when the two differ (a transition); elsewhere a ray keeps its medium.
#pragma once

#include "core/vector.h"
#include "media/medium.h"

namespace candela {

struct MediumInterface {
  const Medium* inside = nullptr;  // null: vacuum
  const Medium* outside = nullptr;
  bool isTransition() const { return inside != outside; }
  // The medium a ray leaving the surface in direction w enters (n: the geometric normal).
  const Medium* entered(const Vector3f& w, const Normal3f& n) const {
    return dot(w, n) > 0 ? outside : inside;
  }
};

}  // namespace candela
