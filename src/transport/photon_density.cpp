#include "transport/photon_density.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace candela {

namespace {

// The nearest photons and the squared radius of the disc they were gathered from: that of the
// farthest one when nUsed were found, else the largest search radius.
std::span<NearPhoton> gather(const PhotonMap& map, const Point3f& p, const DensityEstimate& est,
                             MemoryArena& arena, Float* radius2) {
  auto* buffer = static_cast<NearPhoton*>(arena.alloc(sizeof(NearPhoton) * size_t(est.nUsed)));
  std::span<NearPhoton> all(buffer, size_t(est.nUsed));
  int found = map.nearest(p, est.maxDist2, all);
  *radius2 = found == est.nUsed ? all[found - 1].dist2 : est.maxDist2;
  return all.first(size_t(found));
}

// The lrt draft's outlier filter: drops the nFilter brightest photons when more than twice as
// many were found, and scales the rest up to compensate. Returns the scale (the draft's integer
// division there is a bug; this one is real-valued).
Float dropBrightest(std::span<NearPhoton>* photons, int nFilter) {
  size_t n = photons->size();
  if (nFilter <= 0 || n <= 2 * size_t(nFilter)) return 1;
  auto brighter = [](const NearPhoton& a, const NearPhoton& b) {
    return a.photon->alpha.y() > b.photon->alpha.y();
  };
  std::nth_element(photons->begin(), photons->begin() + nFilter, photons->end(), brighter);
  *photons = photons->subspan(size_t(nFilter));
  return Float(n) / Float(n - size_t(nFilter));
}

}  // namespace

Spectrum photonRadiance(const PhotonMap& map, const Point3f& p, const Vector3f& wo,
                        const BSDF& bsdf, const DensityEstimate& est, MemoryArena& arena) {
  if (map.empty() || est.nUsed <= 0) return Spectrum(0);
  Float r2;
  std::span<NearPhoton> photons = gather(map, p, est, arena, &r2);
  if (photons.empty()) return Spectrum(0);
  Float scale = dropBrightest(&photons, est.nFilter) / Float(map.nPaths());
  Spectrum l(0);
  for (const NearPhoton& np : photons) {
    Float k = simpsonKernel(np.dist2, r2);
    if (k > 0) l += bsdf.f(wo, np.photon->wi) * np.photon->alpha * k;
  }
  return l * scale;
}

Spectrum photonIrradiance(const PhotonMap& map, const Point3f& p, const Normal3f& n,
                          const DensityEstimate& est, MemoryArena& arena, bool excludeAtP) {
  if (map.empty() || est.nUsed <= 0) return Spectrum(0);
  DensityEstimate search = est;
  if (excludeAtP) ++search.nUsed;  // room for the photons at p, which are then dropped
  Float r2;
  std::span<NearPhoton> photons = gather(map, p, search, arena, &r2);
  const bool full = photons.size() == size_t(search.nUsed);
  if (excludeAtP) {
    auto others = std::stable_partition(photons.begin(), photons.end(),
                                        [](const NearPhoton& np) { return np.dist2 > 0; });
    photons = photons.first(size_t(others - photons.begin()));
  }
  // When nUsed were found the farthest one only fixes the disc: counting it too would make the
  // estimate nUsed / (nUsed - 1) too large for uniformly scattered photons (pbrt-v2 counts it).
  if (full && !photons.empty()) photons = photons.first(photons.size() - 1);
  if (photons.empty() || !(r2 > 0)) return Spectrum(0);
  Float scale = dropBrightest(&photons, est.nFilter) / (Float(map.nPaths()) * kPi * r2);
  Spectrum e(0);
  for (const NearPhoton& np : photons)
    if (dot(n, np.photon->wi) > 0) e += np.photon->alpha;
  return e * scale;
}

SearchRadiusCheck checkSearchRadius(const PhotonMap& map, const DensityEstimate& est, int queries) {
  SearchRadiusCheck check;
  if (map.empty() || est.nUsed <= 0 || queries <= 0) return check;
  size_t n = std::min(map.size(), size_t(queries));
  std::vector<NearPhoton> found(size_t(est.nUsed) + 1);
  std::vector<Float> full;
  double total = 0;
  for (size_t q = 0; q < n; ++q) {
    const Point3f& p = map.photons()[q * map.size() / n].p;
    // One more than nUsed: the photon at p itself is found at distance 0. Those of the nearest
    // within the radius are what a lookup there finds.
    int all = map.nearest(p, kInfinity, std::span<NearPhoton>(found));
    int within = int(std::count_if(found.begin(), found.begin() + all,
                                   [&](const NearPhoton& np) { return np.dist2 < est.maxDist2; }));
    total += std::max(0, within - 1);
    full.push_back(std::sqrt(found[size_t(all - 1)].dist2));
  }
  std::nth_element(full.begin(), full.begin() + long(n / 2), full.end());
  check.queries = int(n);
  check.meanFound = std::min(double(est.nUsed), total / double(n));
  check.medianFullRadius = full[n / 2];
  return check;
}

}  // namespace candela
