// Catmull-Rom splines over irregularly spaced nodes (pbrt 3e §8.6.1, §8.6.2): a cubic Hermite
// interpolant whose derivative at each node is the central difference of its neighbours, and the
// one-sided difference at the two ends. Nodes are non-decreasing; a node may repeat once (a
// zero-width interval), which splits the spline into two independent pieces there, as the
// tabulated BSDF files do at mu = 0.
#pragma once

#include <span>

#include "core/common.h"

namespace candela {

// The spline at x as a weighted sum of the values at nodes offset .. offset + 3 (weights of
// nodes outside the table are 0). False when x lies outside [nodes.front(), nodes.back()].
bool catmullRomWeights(std::span<const Float> nodes, Float x, int* offset, Float weights[4]);

// Integral of the spline through (nodes, values) from nodes[0] to each node: cdf[i]; returns the
// total. cdf has the size of nodes.
Float integrateCatmullRom(std::span<const Float> nodes, std::span<const Float> values,
                          std::span<Float> cdf);

// A family of splines over nodes, one per parameter node, stored row by row in values (row r:
// values[r * n .. r * n + n)) with their integrals cdf (integrateCatmullRom per row). The row
// for a parameter alpha is the spline-weighted blend of the rows around it.
struct CatmullRomRows {
  std::span<const Float> paramNodes, nodes, values, cdf;
};

// Draws x with density proportional to the blended row at alpha by inverting its integral
// (pbrt 3e §8.6.2). Returns false when the row is outside the table or integrates to <= 0; else
// *x, the spline's value there (*value) and the density *pdf = value / integral.
bool sampleCatmullRom2D(const CatmullRomRows& rows, Float alpha, Float u, Float* x, Float* value,
                        Float* pdf);

// The blended row at alpha evaluated at x, and its integral (both 0 outside the table).
Float evaluateCatmullRom2D(const CatmullRomRows& rows, Float alpha, Float x, Float* integral);

}  // namespace candela
