// Test helper: intersectCoherent against intersect, for groups of rays like a pixel's camera rays.
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <limits>
#include <vector>

#include "accel/aggregate.h"
#include "support/random_geometry.h"

namespace candela::test {

// Groups of up to eight rays from one origin in nearly one direction, as a pixel's camera rays:
// intersectCoherent (Embree's packets) against intersect one ray at a time. Some groups hold a
// ray that cannot be traced or one stopped short.
struct CoherentFigures {
  long rays = 0, hits = 0, hitMismatch = 0, primMismatch = 0, tMismatch = 0, pointMismatch = 0;
};

inline CoherentFigures compareCoherent(const Aggregate& agg, uint64_t seed, int groups) {
  RNG rng(seed);
  CoherentFigures f;
  for (int g = 0; g < groups; ++g) {
    Point3f o = randomPoint(rng, -8, 8);
    Vector3f centre = randomPoint(rng, -5, 5) - o;
    const int n = 1 + g % 8;
    std::vector<Ray> rays;
    for (int i = 0; i < n; ++i) {
      Vector3f jitter = randomDirection(rng) * (0.02f * centre.length());
      Ray r(o, centre + jitter);
      // Stopped short, or not traceable, in lanes that vary from group to group.
      if (g % 3 == 1 && i == (g / 3) % n) r.tMax = 0.3f * centre.length();
      if (g % 11 == 5 && i == (g / 11) % n) r.d.y = std::numeric_limits<Float>::quiet_NaN();
      rays.push_back(r);
    }
    std::vector<Ray> alone = rays;
    std::vector<SurfaceInteraction> together(static_cast<size_t>(n));
    bool hits[8];
    agg.intersectCoherent(rays, together.data(), hits);
    for (int i = 0; i < n; ++i) {
      ++f.rays;
      SurfaceInteraction one;
      bool hit = agg.intersect(alone[size_t(i)], &one);
      if (hit != hits[i]) {
        ++f.hitMismatch;
        continue;
      }
      if (!hit) {
        EXPECT_EQ(floatToBits(rays[size_t(i)].tMax), floatToBits(alone[size_t(i)].tMax));
        continue;
      }
      ++f.hits;
      const SurfaceInteraction& two = together[size_t(i)];
      f.primMismatch += one.primitive != two.primitive;
      f.tMismatch += floatToBits(alone[size_t(i)].tMax) != floatToBits(rays[size_t(i)].tMax);
      f.pointMismatch +=
          !(one.p == two.p && one.pError == two.pError && one.n == two.n && one.uv == two.uv &&
            one.dpdu == two.dpdu && one.shading.n == two.shading.n && one.wo == two.wo);
    }
  }
  return f;
}

// Prints f and expects no mismatch of any kind.
inline void expectTheSameHits(const CoherentFigures& f) {
  std::printf("[ info ] %ld rays, %ld hits; mismatches: hit %ld, primitive %ld, t %ld, point %ld\n",
              f.rays, f.hits, f.hitMismatch, f.primMismatch, f.tMismatch, f.pointMismatch);
  EXPECT_EQ(f.hitMismatch, 0);
  EXPECT_EQ(f.primMismatch, 0);
  EXPECT_EQ(f.tMismatch, 0);
  EXPECT_EQ(f.pointMismatch, 0);
}

}  // namespace candela::test
