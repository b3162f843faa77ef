// Filter callbacks on a triangle mesh's native Embree geometry (Embree 3 filter functions),
// installed only on the meshes that need them:
// - alpha cut-outs (pbrt-v2's "alpha"/"shadowalpha"): a hit where the mesh's alpha texture is 0
//   at the hit's (u, v) is rejected, so Embree goes on to the next surface;
// - degenerate triangles (zero area, a repeated vertex, a NaN or infinite vertex): Embree's
//   robust test can report a hit on a zero-area triangle when the ray passes through its line
//   (its edge functions round to a common sign); such hits are rejected.
// Internal to src/accel/embree.
#pragma once

#include <embree3/rtcore.h>

namespace candela {

struct TriangleMesh;

// Installs the intersection filter when mesh.alpha is set or mesh has a degenerate triangle, and
// the occlusion filter when mesh.shadowAlpha is set or mesh has one. The geometry's user data
// must be its EmbreeGeometry (Kind::Triangles), whose primitives are TriangleShapes of mesh.
void setTriangleFilters(RTCGeometry geometry, const TriangleMesh& mesh);

}  // namespace candela
