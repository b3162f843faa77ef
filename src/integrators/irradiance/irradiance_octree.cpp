#include "integrators/irradiance/irradiance_octree.h"

namespace candela {

namespace {

// Deep enough for samples a millionth of the scene's size; a node at this depth keeps whatever
// reaches it.
constexpr int kMaxDepth = 16;

bool overlaps(const Bounds3f& a, const Bounds3f& b) {
  return a.pMax.x >= b.pMin.x && a.pMin.x <= b.pMax.x && a.pMax.y >= b.pMin.y &&
         a.pMin.y <= b.pMax.y && a.pMax.z >= b.pMin.z && a.pMin.z <= b.pMax.z;
}

}  // namespace

IrradianceOctree::IrradianceOctree(const Bounds3f& bounds) : bounds_(bounds) {}

int IrradianceOctree::childIndex(const Bounds3f& b, const Point3f& p) {
  Point3f mid = (b.pMin + b.pMax) * 0.5f;
  return (p.x >= mid.x ? 1 : 0) | (p.y >= mid.y ? 2 : 0) | (p.z >= mid.z ? 4 : 0);
}

Bounds3f IrradianceOctree::childBounds(const Bounds3f& b, int child) {
  Point3f mid = (b.pMin + b.pMax) * 0.5f;
  Bounds3f c;
  c.pMin = Point3f(child & 1 ? mid.x : b.pMin.x, child & 2 ? mid.y : b.pMin.y,
                   child & 4 ? mid.z : b.pMin.z);
  c.pMax = Point3f(child & 1 ? b.pMax.x : mid.x, child & 2 ? b.pMax.y : mid.y,
                   child & 4 ? b.pMax.z : mid.z);
  return c;
}

void IrradianceOctree::add(const IrradianceSample& sample) {
  uint32_t index = uint32_t(samples_.size());
  samples_.push_back(sample);
  Vector3f r(sample.radius, sample.radius, sample.radius);
  Bounds3f extent(sample.p - r, sample.p + r);
  if (overlaps(extent, bounds_)) addTo(root_, bounds_, index, extent, 0);
}

void IrradianceOctree::addTo(Node& node, const Bounds3f& nodeBounds, uint32_t index,
                             const Bounds3f& extent, int depth) {
  // A node no larger than the sample's extent keeps it: going deeper would copy the index into
  // many children for no gain in lookup work.
  if (depth == kMaxDepth ||
      nodeBounds.diagonal().lengthSquared() < extent.diagonal().lengthSquared()) {
    node.samples.push_back(index);
    ++references_;
    return;
  }
  for (int c = 0; c < 8; ++c) {
    Bounds3f cb = childBounds(nodeBounds, c);
    if (!overlaps(cb, extent)) continue;
    if (!node.children[c]) {
      node.children[c] = std::make_unique<Node>();
      ++nodes_;
    }
    addTo(*node.children[c], cb, index, extent, depth + 1);
  }
}

size_t IrradianceOctree::memoryBytes() const {
  return sizeof(*this) + samples_.capacity() * sizeof(IrradianceSample) + nodes_ * sizeof(Node) +
         references_ * sizeof(uint32_t);
}

}  // namespace candela
