// The hierarchical evaluation of the dipole's sum over irradiance samples (Jensen and Buhler 2002,
// "A Rapid Hierarchical Rendering Technique for Translucent Materials"; pbrt 2e §16.5): an octree
// over the points whose nodes keep the sum of E A of the points below and their irradiance-
// weighted mean position. A node whose points are seen from the shading point under a solid angle
// (their area over the squared distance to that position) below maxError, and which does not
// contain the shading point, stands in for all of them with one evaluation of Rd.
#pragma once

#include <vector>

#include "core/bounds.h"
#include "reflection/dipole.h"
#include "transport/subsurface_points.h"

namespace candela {

class SubsurfaceOctree {
 public:
  SubsurfaceOctree() = default;
  // Takes the points (reordered into leaf order).
  explicit SubsurfaceOctree(std::vector<SubsurfacePoint> points);
  // sum over points of Rd(|p - p_i|) E_i A_i, hierarchically with the maxError criterion.
  Spectrum sum(const Point3f& p, const DipoleProfile& rd, Float maxError) const;
  // The same sum over every point, one by one (the reference for the tests).
  Spectrum bruteForceSum(const Point3f& p, const DipoleProfile& rd) const;
  bool empty() const { return points_.empty(); }
  size_t pointCount() const { return points_.size(); }
  size_t nodeCount() const { return nodes_.size(); }
  size_t memoryBytes() const;
  const std::vector<SubsurfacePoint>& points() const { return points_; }

 private:
  struct Node {
    Bounds3f bounds;
    Point3f p;                    // irradiance-weighted mean position of the points below
    Spectrum sumEA;               // sum of E A below
    Float sumA = 0;               // area below
    int32_t firstChild = -1;      // index of 8 consecutive children; -1: a leaf
    uint32_t begin = 0, end = 0;  // the points below, in points_
  };
  void build(size_t index, const Bounds3f& bounds, uint32_t begin, uint32_t end, int depth);
  Spectrum sumNode(const Node& node, const Point3f& p, const DipoleProfile& rd,
                   Float maxError) const;

  std::vector<SubsurfacePoint> points_;
  std::vector<Node> nodes_;
};

}  // namespace candela
