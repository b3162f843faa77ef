// Moving a surface interaction from an instance's own space to world space (pbrt 3e §2.10.4;
// the lrt draft's InstancePrimitive transforms its DifferentialGeometry the same way, §4.1.2).
// Every aggregate that holds instances uses it, so that Embree and the book's aggregates report
// the same interaction for the same hit.
#pragma once

#include "core/interaction.h"
#include "core/transform.h"

namespace candela {

// The point goes through Transform::apply with its error bound, so pError grows by the
// transform's rounding; dp/du and dp/dv as vectors; normals and dn/du, dn/dv by the inverse
// transpose (which keeps a normal on the side it was on, also through mirroring transforms),
// then the normals renormalised and the shading normal turned to the geometric normal's side.
// wo is taken from the world ray (worldRayD) rather than transformed, so that it is exactly
// -normalize(worldRayD) as for hits outside instances. uv, time and primitive are copied.
SurfaceInteraction transformSurfaceInteraction(const Transform& toWorld,
                                               const SurfaceInteraction& si,
                                               const Vector3f& worldRayD);

}  // namespace candela
