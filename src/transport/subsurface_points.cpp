#include "transport/subsurface_points.h"

#include <oneapi/tbb/task_arena.h>

#include <cmath>
#include <unordered_map>

#include "accel/primitive.h"
#include "core/parallel_for.h"
#include "core/rng.h"
#include "core/sampling.h"
#include "materials/material.h"

namespace candela {

namespace {

// Seeds of the random sequences, one family per use.
uint64_t mixSeed(uint64_t seed, uint64_t purpose) {
  uint64_t z = seed + 0x9e3779b97f4a7c15ULL * (purpose + 1);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}
constexpr uint64_t kProbeLines = 1, kPlacementLines = 2, kIrradiance = 3;

struct Crossing {
  Point3f p;
  Normal3f n;
  Vector3f pError;
};

// One isotropic random line across the sphere (center, radius): the translucent crossings along
// it, in order, appended to *out.
void traceLine(const Scene& scene, const Point3f& center, Float radius, Float time, RNG& rng,
               std::vector<Crossing>* out, RayStats& stats) {
  Float u0 = rng.uniformFloat(), u1 = rng.uniformFloat();
  Vector3f d = sampleUniformSphere({u0, u1});
  Float u2 = rng.uniformFloat(), u3 = rng.uniformFloat();
  Point2f disk = sampleUniformDiskConcentric({u2, u3});
  Vector3f s, t;
  coordinateSystem(d, &s, &t);
  Point3f o = center + s * (disk.x * radius) + t * (disk.y * radius) - d * radius;
  Float length = 2 * radius;  // the chord's bound: only crossings inside the sphere count
  Ray ray(o, d, length, time);
  constexpr int kMaxCrossings = 1024;
  for (int i = 0; i < kMaxCrossings; ++i) {
    SurfaceInteraction isect;
    if (!scene.intersect(ray, &isect, stats)) return;
    const Material* m = isect.primitive ? isect.primitive->material : nullptr;
    if (m && m->subsurface()) out->push_back({isect.p, isect.n, isect.pError});
    Float travelled = dot(isect.p - o, d);
    if (!(travelled < length)) return;
    ray = isect.spawnRay(d);
    ray.tMax = length - travelled;
    ray.time = time;
  }
}

// Lines [first, first + count) of one family, traced in parallel; crossings in line order.
std::vector<Crossing> traceLines(const Scene& scene, const Point3f& center, Float radius,
                                 Float time, uint64_t familySeed, uint64_t first, uint64_t count,
                                 tbb::task_arena& arena, RayStats& stats) {
  constexpr uint64_t kBlock = 256;
  uint64_t blocks = (count + kBlock - 1) / kBlock;
  std::vector<std::vector<Crossing>> found(blocks);
  std::vector<RayStats> blockStats(blocks);
  parallelFor(arena, uint64_t(0), blocks, [&](uint64_t b) {
    for (uint64_t i = first + b * kBlock; i < std::min(first + count, first + (b + 1) * kBlock);
         ++i) {
      RNG rng(i, familySeed);
      traceLine(scene, center, radius, time, rng, &found[b], blockStats[b]);
    }
  });
  std::vector<Crossing> all;
  for (uint64_t b = 0; b < blocks; ++b) {
    all.insert(all.end(), found[b].begin(), found[b].end());
    stats += blockStats[b];
  }
  return all;
}

// Kept points hashed by cell of side minDistance: a candidate's neighbours within minDistance lie
// in the 27 cells around its own.
class PointGrid {
 public:
  explicit PointGrid(Float cell) : invCell_(1 / cell) {}
  void insert(const Point3f& p, uint32_t index) { cells_[keyOf(p)].push_back(index); }
  // The index of the nearest point within distance r of p (r <= cell), or -1.
  int64_t nearestWithin(const Point3f& p, Float r, const std::vector<SubsurfacePoint>& pts) const {
    Key k = keyOf(p);
    int64_t best = -1;
    Float bestD2 = r * r;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          auto it = cells_.find({k.x + dx, k.y + dy, k.z + dz});
          if (it == cells_.end()) continue;
          for (uint32_t i : it->second) {
            Float d2 = distanceSquared(p, pts[i].p);
            if (d2 < bestD2 || (d2 == bestD2 && best < 0)) {
              bestD2 = d2;
              best = i;
            }
          }
        }
    return best;
  }
  size_t memoryBytes() const {
    size_t bytes = cells_.bucket_count() * sizeof(void*);
    for (const auto& [k, v] : cells_) bytes += sizeof(k) + sizeof(v) + v.capacity() * 4 + 16;
    return bytes;
  }

 private:
  struct Key {
    int64_t x, y, z;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    size_t operator()(const Key& k) const {
      return size_t(mixSeed(uint64_t(k.x) * 73856093u ^ uint64_t(k.y) * 19349663u, uint64_t(k.z)));
    }
  };
  Key keyOf(const Point3f& p) const {
    return {int64_t(std::floor(p.x * invCell_)), int64_t(std::floor(p.y * invCell_)),
            int64_t(std::floor(p.z * invCell_))};
  }
  Float invCell_;
  std::unordered_map<Key, std::vector<uint32_t>, KeyHash> cells_;
};

}  // namespace

SubsurfacePointSet placeSubsurfacePoints(const Scene& scene,
                                         const SubsurfacePlacementOptions& options) {
  SubsurfacePointSet set;
  set.time = options.time;
  Bounds3f sceneBounds = scene.worldBound();
  Point3f center;
  Float radius = 0;
  sceneBounds.boundingSphere(&center, &radius);
  if (!(radius > 0 && std::isfinite(radius))) return set;
  int threads = options.nThreads > 0 ? options.nThreads : tbb::info::default_concurrency();
  tbb::task_arena arena(threads);

  // Probe lines across the whole scene find where the translucent surfaces are, so that the
  // placement lines need not cross empty space.
  constexpr uint64_t kProbeCount = 16384;
  std::vector<Crossing> probe =
      traceLines(scene, center, radius, options.time, mixSeed(options.seed, kProbeLines), 0,
                 kProbeCount, arena, set.rays);
  if (probe.empty()) return set;
  Bounds3f found;
  for (const Crossing& c : probe) found = unionOf(found, c.p);
  // A margin for the parts the probes missed: a quarter of the extent, and minDistance.
  Float margin = std::max(found.diagonal().length() / 4, options.minDistance);
  found = Bounds3f(found.pMin - Vector3f(margin, margin, margin),
                   found.pMax + Vector3f(margin, margin, margin));
  Float placementRadius;
  Point3f placementCenter;
  found.boundingSphere(&placementCenter, &placementRadius);
  if (placementRadius > radius) {
    placementCenter = center;
    placementRadius = radius;
  }

  // Dart throwing over the crossings, batch after batch of lines, until kMaxFails candidates in a
  // row found a kept point near (the surface is covered) and there are kCrossingsPerPoint
  // crossings per point for the areas.
  constexpr uint64_t kMaxFails = 2000, kCrossingsPerPoint = 32, kBatch = 16384;
  constexpr uint64_t kMaxLines = uint64_t(1) << 26;
  const Float minDistance = options.minDistance;
  PointGrid grid(minDistance);
  std::vector<Point3f> crossings;
  uint64_t fails = 0;
  uint64_t familySeed = mixSeed(options.seed, kPlacementLines);
  while (set.linesTraced < kMaxLines) {
    std::vector<Crossing> batch = traceLines(scene, placementCenter, placementRadius, options.time,
                                             familySeed, set.linesTraced, kBatch, arena, set.rays);
    set.linesTraced += kBatch;
    for (const Crossing& c : batch) {
      crossings.push_back(c.p);
      if (set.points.size() < options.maxPoints &&
          grid.nearestWithin(c.p, minDistance, set.points) < 0) {
        grid.insert(c.p, uint32_t(set.points.size()));
        set.points.push_back({c.p, c.n, c.pError, 0, Spectrum(0)});
        fails = 0;
      } else {
        ++fails;
      }
    }
    if (set.points.size() >= options.maxPoints || crossings.size() >= options.maxCrossings)
      set.reachedPointLimit = true;
    bool covered = fails >= kMaxFails || set.reachedPointLimit;
    if (covered && (crossings.size() >= kCrossingsPerPoint * set.points.size() ||
                    crossings.size() >= options.maxCrossings))
      break;
    // Nothing translucent inside the placement sphere after many lines: stop.
    if (crossings.empty() && set.linesTraced >= 16 * kBatch) break;
  }
  set.candidates = crossings.size();

  // Crofton: each crossing stands for 2 pi R^2 / lines of surface; it goes to the nearest kept
  // point (one lies within minDistance of every crossing unless the point limit was reached).
  Float areaPerCrossing = 2 * kPi * placementRadius * placementRadius / Float(set.linesTraced);
  set.surfaceArea = areaPerCrossing * Float(crossings.size());
  for (const Point3f& p : crossings) {
    int64_t nearest = grid.nearestWithin(p, minDistance, set.points);
    if (nearest >= 0) set.points[size_t(nearest)].area += areaPerCrossing;
  }
  return set;
}

void computeDirectIrradiance(const Scene& scene, uint64_t seed, int nThreads, Float sampleScale,
                             SubsurfacePointSet* set) {
  int threads = nThreads > 0 ? nThreads : tbb::info::default_concurrency();
  tbb::task_arena arena(threads);
  uint64_t familySeed = mixSeed(seed, kIrradiance);
  constexpr size_t kBlock = 64;
  size_t n = set->points.size();
  size_t blocks = (n + kBlock - 1) / kBlock;
  std::vector<RayStats> blockStats(blocks);
  parallelFor(arena, size_t(0), blocks, [&](size_t b) {
    for (size_t i = b * kBlock; i < std::min(n, (b + 1) * kBlock); ++i) {
      SubsurfacePoint& sp = set->points[i];
      RNG rng(i, familySeed);
      Interaction ref(sp.p, sp.n, sp.pError, Vector3f(sp.n), set->time);
      Spectrum e(0);
      for (const Light* light : scene.lights()) {
        int samples = std::max(1, int(std::lround(light->nSamples() * sampleScale)));
        Spectrum sum(0);
        for (int s = 0; s < samples; ++s) {
          Float u0 = rng.uniformFloat(), u1 = rng.uniformFloat();
          Vector3f wi;
          Float pdf = 0;
          VisibilityTester vis;
          Spectrum li = light->sampleLi(ref, {u0, u1}, &wi, &pdf, &vis);
          if (pdf == 0 || li.isBlack()) continue;
          Float cosTheta = absDot(wi, sp.n);
          if (cosTheta == 0 || !scene.unoccluded(vis, blockStats[b])) continue;
          sum += li * (cosTheta / pdf);
        }
        e += sum / Float(samples);
      }
      sp.E = e;
    }
  });
  for (const RayStats& s : blockStats) set->rays += s;
}

}  // namespace candela
