#include "accel/grid/grid_aggregate.h"

#include <cmath>

#include "accel/mailbox.h"
#include "accel/ray_query.h"

namespace candela {

namespace {
constexpr int kMaxVoxelsPerAxis = 64;  // lrt draft §4.3.1

// Items are entered in every voxel their bound, widened by this fraction of a voxel, overlaps:
// the walk below places the ray in voxels by floating-point arithmetic, which can put a point
// within rounding error of a voxel face on the wrong side of it. The error is a few ulps of the
// coordinates along the ray, far below 1% of a voxel (1/6400 of the grid at most) for rays
// starting within ~1000 grid diagonals of the grid.
constexpr Float kVoxelPad = 0.01f;
}  // namespace

std::array<int, 3> GridAggregate::resolution(const Bounds3f& bounds, size_t nItems) {
  std::array<int, 3> n = {1, 1, 1};
  if (bounds.empty() || nItems == 0) return n;
  Vector3f delta = bounds.diagonal();
  Float maxWidth = delta[bounds.maximumExtent()];
  if (!(maxWidth > 0)) return n;  // every item at one point
  Float cubeRoot = 3 * std::cbrt(Float(nItems));
  Float voxelsPerUnitDist = cubeRoot / maxWidth;
  for (int a = 0; a < 3; ++a)
    n[a] = clamp(int(std::lround(delta[a] * voxelsPerUnitDist)), 1, kMaxVoxelsPerAxis);
  return n;
}

GridAggregate::GridAggregate(std::span<const Primitive> primitives) : items_(primitives) {
  build();
}

GridAggregate::GridAggregate(const SceneGeometry& geometry)
    : items_(geometry, [](std::span<const Primitive> prims) {
        return std::make_unique<GridAggregate>(prims);
      }) {
  build();
}

int GridAggregate::posToVoxel(Float p, int axis) const {
  Float v = (p - bounds_.pMin[axis]) * invWidth_[axis];
  // Clamped in float first: a far-off point must not overflow the int conversion. A grid whose
  // extent overflows float (vertices at +-3.4e38) has an infinite width and 1/width = 0, and
  // inf * 0 is a NaN: voxel 0 then, not the undefined int(NaN) (which crashed).
  if (!(v > 0)) return 0;
  return int(std::min(v, Float(n_[axis] - 1)));
}

void GridAggregate::build() {
  uint32_t count = items_.size();
  std::vector<Bounds3f> bounds(count);
  size_t nonEmpty = 0;
  for (uint32_t i = 0; i < count; ++i) {
    bounds[i] = items_.bound(i);
    if (bounds[i].empty()) continue;
    bounds_ = unionOf(bounds_, bounds[i]);
    ++nonEmpty;
  }
  n_ = resolution(bounds_, nonEmpty);
  if (nonEmpty == 0) {
    voxelStart_.assign(2, 0);
    return;
  }
  // Voxel widths; a zero-width axis has one voxel and 1/width = 0 (inventory §23), so every
  // position maps to voxel 0 there.
  Vector3f delta = bounds_.diagonal();
  for (int a = 0; a < 3; ++a) {
    width_[a] = delta[a] / n_[a];
    invWidth_[a] = width_[a] == 0 ? 0 : 1 / width_[a];
  }

  // The voxel range of each item, then a counting pass and a filling pass (compressed rows).
  size_t nVoxels = size_t(n_[0]) * n_[1] * n_[2];
  auto range = [&](const Bounds3f& b, int lo[3], int hi[3]) {
    for (int a = 0; a < 3; ++a) {
      Float pad = kVoxelPad * width_[a];
      lo[a] = posToVoxel(b.pMin[a] - pad, a);
      hi[a] = posToVoxel(b.pMax[a] + pad, a);
    }
  };
  voxelStart_.assign(nVoxels + 1, 0);
  for (uint32_t i = 0; i < count; ++i) {
    if (bounds[i].empty()) continue;
    int lo[3], hi[3];
    range(bounds[i], lo, hi);
    for (int z = lo[2]; z <= hi[2]; ++z)
      for (int y = lo[1]; y <= hi[1]; ++y)
        for (int x = lo[0]; x <= hi[0]; ++x) ++voxelStart_[x + n_[0] * (y + n_[1] * z) + 1];
  }
  for (size_t v = 0; v < nVoxels; ++v) voxelStart_[v + 1] += voxelStart_[v];
  voxelItems_.resize(voxelStart_[nVoxels]);
  std::vector<uint32_t> fill(voxelStart_.begin(), voxelStart_.end() - 1);
  for (uint32_t i = 0; i < count; ++i) {
    if (bounds[i].empty()) continue;
    int lo[3], hi[3];
    range(bounds[i], lo, hi);
    for (int z = lo[2]; z <= hi[2]; ++z)
      for (int y = lo[1]; y <= hi[1]; ++y)
        for (int x = lo[0]; x <= hi[0]; ++x) voxelItems_[fill[x + n_[0] * (y + n_[1] * z)]++] = i;
  }
}

// The 3D-DDA of the draft (§4.3.2). One difference: the draft advances each axis's next crossing
// by adding DeltaT, which accumulates one rounding per step; here every crossing is computed
// afresh from the entry point, so its error stays a few ulps however far the walk goes.
template <typename VisitVoxel>
bool GridAggregate::walk(const Ray& ray, VisitVoxel&& visitVoxel) const {
  RaySlabs slabs(ray);
  Float t0, t1;
  if (!clipToBox(bounds_, slabs, 0, ray.tMax, &t0, &t1)) return false;
  Point3f entry = ray(t0);
  int pos[3], step[3], out[3];
  Float next[3];
  for (int a = 0; a < 3; ++a) {
    pos[a] = posToVoxel(entry[a], a);
    if (ray.d[a] > 0) {
      step[a] = 1;
      out[a] = n_[a];
      next[a] = t0 + (voxelToPos(pos[a] + 1, a) - entry[a]) * slabs.invDir[a];
    } else if (ray.d[a] < 0) {
      step[a] = -1;
      out[a] = -1;
      next[a] = t0 + (voxelToPos(pos[a], a) - entry[a]) * slabs.invDir[a];
    } else {
      // A zero component (either sign): this axis is never crossed (inventory §23).
      step[a] = 0;
      out[a] = -1;
      next[a] = kInfinity;
    }
  }
  for (;;) {
    size_t v = size_t(pos[0]) + size_t(n_[0]) * (size_t(pos[1]) + size_t(n_[1]) * pos[2]);
    uint32_t begin = voxelStart_[v], end = voxelStart_[v + 1];
    if (begin != end && visitVoxel(begin, end)) return true;
    // The axis whose voxel face comes first.
    int axis = next[0] < next[1] ? (next[0] < next[2] ? 0 : 2) : (next[1] < next[2] ? 1 : 2);
    // A hit before that face ends the walk: items past it are hit later (or are also entered
    // in this voxel, by the padding above).
    if (ray.tMax < next[axis]) return false;
    pos[axis] += step[axis];
    if (pos[axis] == out[axis]) return false;
    next[axis] = t0 + (voxelToPos(pos[axis] + (step[axis] > 0 ? 1 : 0), axis) - entry[axis]) *
                          slabs.invDir[axis];
  }
}

bool GridAggregate::intersect(const Ray& ray, SurfaceInteraction* isect) const {
  if (!isTraceableRay(ray) || items_.empty()) return false;
  RayMailbox mailbox;
  bool hit = false;
  walk(ray, [&](uint32_t begin, uint32_t end) {
    for (uint32_t k = begin; k < end; ++k) {
      uint32_t item = voxelItems_[k];
      if (mailbox.testedBefore(item)) continue;
      if (items_.intersect(item, ray, isect)) hit = true;
    }
    return false;  // the walk decides when the hit is final
  });
  return hit;
}

bool GridAggregate::intersectP(const Ray& ray) const {
  if (!isTraceableRay(ray) || items_.empty()) return false;
  RayMailbox mailbox;
  return walk(ray, [&](uint32_t begin, uint32_t end) {
    for (uint32_t k = begin; k < end; ++k) {
      uint32_t item = voxelItems_[k];
      if (!mailbox.testedBefore(item) && items_.intersectP(item, ray)) return true;
    }
    return false;
  });
}

AggregateStats GridAggregate::stats() const {
  AggregateStats s;
  s.name = "grid";
  long nonEmpty = 0;
  for (size_t v = 0; v + 1 < voxelStart_.size(); ++v)
    nonEmpty += voxelStart_[v + 1] > voxelStart_[v];
  s.counts["voxels"] = long(n_[0]) * n_[1] * n_[2];
  s.counts["nonempty voxels"] = nonEmpty;
  s.counts["references"] = long(voxelItems_.size());
  s.counts["items"] = long(items_.size());
  s.counts["instances"] = items_.instanceCount();
  s.counts["prototypes"] = items_.prototypeCount();
  s.counts["bytes"] = long(sizeof(*this) + voxelStart_.capacity() * sizeof(uint32_t) +
                           voxelItems_.capacity() * sizeof(uint32_t)) +
                      items_.bytes();
  return s;
}

}  // namespace candela
