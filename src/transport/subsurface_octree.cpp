#include "transport/subsurface_octree.h"

#include <algorithm>

namespace candela {

namespace {
constexpr uint32_t kMaxLeafPoints = 8;
constexpr int kMaxDepth = 24;
}  // namespace

SubsurfaceOctree::SubsurfaceOctree(std::vector<SubsurfacePoint> points)
    : points_(std::move(points)) {
  if (points_.empty()) return;
  Bounds3f bounds;
  for (const SubsurfacePoint& sp : points_) bounds = unionOf(bounds, sp.p);
  nodes_.resize(1);
  build(0, bounds, 0, uint32_t(points_.size()), 0);
}

void SubsurfaceOctree::build(size_t index, const Bounds3f& bounds, uint32_t begin, uint32_t end,
                             int depth) {
  // The node is filled in a local and stored at the end: building children resizes nodes_.
  Node node;
  node.bounds = bounds;
  node.begin = begin;
  node.end = end;
  Vector3f weighted(0, 0, 0), byArea(0, 0, 0);
  Float weight = 0;
  for (uint32_t i = begin; i < end; ++i) {
    const SubsurfacePoint& sp = points_[i];
    node.sumEA += sp.E * sp.area;
    node.sumA += sp.area;
    Float w = sp.E.y() * sp.area;
    weighted += Vector3f(sp.p) * w;
    weight += w;
    byArea += Vector3f(sp.p) * sp.area;
  }
  if (weight > 0)
    node.p = Point3f(weighted / weight);
  else if (node.sumA > 0)
    node.p = Point3f(byArea / node.sumA);
  else if (end > begin)
    node.p = points_[begin].p;
  if (end - begin > kMaxLeafPoints && depth < kMaxDepth) {
    // Octants about the box centre (bit 0: x above it, bit 1: y, bit 2: z).
    Point3f mid = (bounds.pMin + bounds.pMax) * Float(0.5);
    auto octant = [&](const Point3f& p) {
      return (p.x > mid.x ? 1 : 0) | (p.y > mid.y ? 2 : 0) | (p.z > mid.z ? 4 : 0);
    };
    std::stable_sort(points_.begin() + begin, points_.begin() + end,
                     [&](const SubsurfacePoint& a, const SubsurfacePoint& b) {
                       return octant(a.p) < octant(b.p);
                     });
    size_t first = nodes_.size();
    nodes_.resize(first + 8);
    uint32_t start = begin;
    for (int o = 0; o < 8; ++o) {
      uint32_t stop = start;
      while (stop < end && octant(points_[stop].p) == o) ++stop;
      Point3f lo((o & 1) ? mid.x : bounds.pMin.x, (o & 2) ? mid.y : bounds.pMin.y,
                 (o & 4) ? mid.z : bounds.pMin.z);
      Point3f hi((o & 1) ? bounds.pMax.x : mid.x, (o & 2) ? bounds.pMax.y : mid.y,
                 (o & 4) ? bounds.pMax.z : mid.z);
      build(first + size_t(o), Bounds3f(lo, hi), start, stop, depth + 1);
      start = stop;
    }
    node.firstChild = int32_t(first);
  }
  nodes_[index] = node;
}

Spectrum SubsurfaceOctree::sum(const Point3f& p, const DipoleProfile& rd, Float maxError) const {
  if (nodes_.empty()) return Spectrum(0);
  return sumNode(nodes_[0], p, rd, maxError);
}

Spectrum SubsurfaceOctree::sumNode(const Node& node, const Point3f& p, const DipoleProfile& rd,
                                   Float maxError) const {
  if (node.begin == node.end) return Spectrum(0);
  Float d2 = distanceSquared(p, node.p);
  // Jensen and Buhler 2002: the node's solid angle A / d^2 against the error bound.
  if (node.firstChild >= 0 && d2 > 0 && node.sumA < maxError * d2 && !node.bounds.inside(p))
    return rd.Rd(d2) * node.sumEA;
  if (node.firstChild < 0) {
    Spectrum s(0);
    for (uint32_t i = node.begin; i < node.end; ++i)
      s += rd.Rd(distanceSquared(p, points_[i].p)) * (points_[i].E * points_[i].area);
    return s;
  }
  Spectrum s(0);
  for (int o = 0; o < 8; ++o) s += sumNode(nodes_[size_t(node.firstChild + o)], p, rd, maxError);
  return s;
}

Spectrum SubsurfaceOctree::bruteForceSum(const Point3f& p, const DipoleProfile& rd) const {
  Spectrum s(0);
  for (const SubsurfacePoint& sp : points_) s += rd.Rd(distanceSquared(p, sp.p)) * (sp.E * sp.area);
  return s;
}

size_t SubsurfaceOctree::memoryBytes() const {
  return nodes_.capacity() * sizeof(Node) + points_.capacity() * sizeof(SubsurfacePoint);
}

}  // namespace candela
