// The choice of normal for the "hyperboloid" shape, on its own so that the scene layer can carry it
// (BuildOptions, --hyperboloid-normal) without the shape's header.
#pragma once

namespace candela {

// Exact: dp/dv is the derivative of the parameterisation on the fitted surface, so the normal is
// the surface's. SegmentAsPbrt: dp/dv is the p1-p2 segment's direction turned by phi, as pbrt-v2
// and v3 compute it (pbrt 3e §3.5.3); it is tangent only where the segment is a ruling of the
// fitted surface, so elsewhere the normal leans off the surface's and both shading and the
// reflect/transmit test use the leaning one.
enum class HyperboloidNormal { Exact, SegmentAsPbrt };

}  // namespace candela
