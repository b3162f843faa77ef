#include "transport/photon_map.h"

namespace candela {

namespace {

template <typename T>
PointKdTree<3> treeOf(const std::vector<T>& items) {
  std::vector<PointKdTree<3>::Point> points;
  points.reserve(items.size());
  for (const T& item : items) points.push_back({item.p.x, item.p.y, item.p.z});
  return PointKdTree<3>(std::move(points));
}

}  // namespace

PhotonMap::PhotonMap(std::vector<Photon> photons, uint64_t nPaths)
    : photons_(std::move(photons)), nPaths_(nPaths), tree_(treeOf(photons_)) {
  photons_.shrink_to_fit();
}

size_t PhotonMap::memoryBytes() const {
  return photons_.capacity() * sizeof(Photon) + tree_.memoryBytes();
}

int PhotonMap::nearest(const Point3f& p, Float maxDist2, std::span<NearPhoton> out) const {
  constexpr int kChunk = 256;
  int k = int(out.size());
  // Small k (the usual case) uses the stack; larger k a heap buffer.
  uint32_t stackIdx[kChunk];
  Float stackD2[kChunk];
  std::vector<uint32_t> heapIdx;
  std::vector<Float> heapD2;
  uint32_t* idx = stackIdx;
  Float* d2 = stackD2;
  if (k > kChunk) {
    heapIdx.resize(k);
    heapD2.resize(k);
    idx = heapIdx.data();
    d2 = heapD2.data();
  }
  int found = tree_.nearestWithin({p.x, p.y, p.z}, k, maxDist2, idx, d2);
  for (int i = 0; i < found; ++i) out[i] = NearPhoton{&photons_[idx[i]], d2[i]};
  return found;
}

RadiancePhotonMap::RadiancePhotonMap(std::vector<RadiancePhoton> photons)
    : photons_(std::move(photons)), tree_(treeOf(photons_)) {
  photons_.shrink_to_fit();
}

size_t RadiancePhotonMap::memoryBytes() const {
  return photons_.capacity() * sizeof(RadiancePhoton) + tree_.memoryBytes();
}

const RadiancePhoton* RadiancePhotonMap::nearest(const Point3f& p, const Normal3f& n) const {
  uint32_t index;
  Float d2;
  auto sameSide = [&](uint32_t i) { return dot(photons_[i].n, n) > 0; };
  int found = tree_.nearestMatching({p.x, p.y, p.z}, 1, kInfinity, sameSide, &index, &d2);
  return found ? &photons_[index] : nullptr;
}

}  // namespace candela
