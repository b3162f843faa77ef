// Photon maps (pbrt 2e §15.6; Jensen 2001): photons stored where particle paths met non-specular
// surfaces, searched by position in a kd-tree. A photon's alpha is its path weight (eq. 15.16); the
// flux it carries is alpha / nPaths, nPaths being the number of paths shot while the map filled.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/spectrum.h"
#include "core/vector.h"
#include "reflection/point_kdtree.h"

namespace candela {

struct Photon {
  Point3f p;
  Spectrum alpha;
  Vector3f wi;  // unit, pointing back along the path toward where the photon came from
};

// One photon found near a lookup point.
struct NearPhoton {
  const Photon* photon;
  Float dist2;
};

class PhotonMap {
 public:
  PhotonMap() = default;
  PhotonMap(std::vector<Photon> photons, uint64_t nPaths);
  size_t size() const { return photons_.size(); }
  bool empty() const { return photons_.empty(); }
  uint64_t nPaths() const { return nPaths_; }
  size_t memoryBytes() const;
  std::span<const Photon> photons() const { return photons_; }

  // The up to out.size() nearest photons strictly within sqrt(maxDist2) of p, nearest first.
  // Returns how many were written to out.
  int nearest(const Point3f& p, Float maxDist2, std::span<NearPhoton> out) const;

 private:
  std::vector<Photon> photons_;
  uint64_t nPaths_ = 0;
  PointKdTree<3> tree_;
};

// pbrt 2e §15.6.3: the radiance leaving a diffuse approximation of the surface at a photon's
// position, precomputed so that a final-gather ray needs one nearest-neighbour lookup.
struct RadiancePhoton {
  Point3f p;
  Normal3f n;   // facing the side the photon arrived from
  Spectrum Lo;  // exitant radiance toward n's side
};

class RadiancePhotonMap {
 public:
  RadiancePhotonMap() = default;
  explicit RadiancePhotonMap(std::vector<RadiancePhoton> photons);
  size_t size() const { return photons_.size(); }
  bool empty() const { return photons_.empty(); }
  size_t memoryBytes() const;
  // The nearest radiance photon whose normal lies in n's hemisphere (so light does not leak
  // through thin surfaces), or nullptr.
  const RadiancePhoton* nearest(const Point3f& p, const Normal3f& n) const;
  std::span<const RadiancePhoton> photons() const { return photons_; }

 private:
  std::vector<RadiancePhoton> photons_;
  PointKdTree<3> tree_;
};

}  // namespace candela
