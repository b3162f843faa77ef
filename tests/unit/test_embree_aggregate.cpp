// The Embree aggregate against a brute-force loop over the same primitives; rays spawned from
// hits (near the origin, far from it, tiny and huge) never re-hit the surface they leave; bad rays
// miss.
#include <gtest/gtest.h>

#include <thread>

#include "accel/embree/embree_aggregate.h"
#include "core/rng.h"
#include "core/sampling.h"
#include "shapes/sphere.h"
#include "shapes/triangle_mesh.h"
#include "support/coherent_rays.h"
#include "support/random_geometry.h"
#include "support/test_device.h"

namespace candela {
namespace {

// Shapes and meshes with their primitives; the primitive vector does not move once built.
struct TestScene {
  std::vector<std::unique_ptr<TriangleMesh>> meshes;
  std::vector<std::unique_ptr<Shape>> shapes;
  std::vector<Primitive> primitives;

  void add(std::unique_ptr<Shape> s) {
    primitives.push_back(Primitive{s.get(), nullptr, nullptr});
    shapes.push_back(std::move(s));
  }
  // Adds triangles [begin, end) of the mesh.
  void addTriangles(const TriangleMesh* mesh, int begin, int end) {
    for (int i = begin; i < end; ++i) add(std::make_unique<TriangleShape>(mesh, i));
  }
  const TriangleMesh* addMesh(std::unique_ptr<TriangleMesh> m) {
    meshes.push_back(std::move(m));
    return meshes.back().get();
  }

  // The reference: every primitive's own intersection, keeping the closest.
  bool bruteIntersect(const Ray& ray, Float* tHit, const Primitive** prim) const {
    Ray r = ray;
    bool hit = false;
    for (const Primitive& p : primitives) {
      Float t;
      if (p.shape->intersect(r, &t, nullptr)) {
        r.tMax = t;
        *tHit = t;
        *prim = &p;
        hit = true;
      }
    }
    return hit;
  }
  bool bruteIntersectP(const Ray& ray) const {
    for (const Primitive& p : primitives)
      if (p.shape->intersectP(ray)) return true;
    return false;
  }
};

// A height field of size n x n over [-5, 5]^2, with per-vertex normals.
std::unique_ptr<TriangleMesh> terrain(int n, const Transform& t) {
  std::vector<Point3f> p;
  std::vector<Normal3f> nrm;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      Float x = -5 + 10.f * i / n, y = -5 + 10.f * j / n;
      p.emplace_back(x, y, 0.5f * std::sin(x) * std::cos(y) - 2);
      nrm.push_back(normalize(
          Normal3f(-0.5f * std::cos(x) * std::cos(y), 0.5f * std::sin(x) * std::sin(y), 1)));
    }
  std::vector<int> idx;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      int v00 = j * (n + 1) + i, v10 = v00 + 1, v01 = v00 + n + 1, v11 = v01 + 1;
      idx.insert(idx.end(), {v00, v10, v11, v00, v11, v01});
    }
  return std::make_unique<TriangleMesh>(t, false, idx, p, nrm);
}

// Random triangles of size ~1 in [-4, 4]^3.
std::unique_ptr<TriangleMesh> soup(int n, RNG& rng, const Transform& t) {
  std::vector<Point3f> p;
  std::vector<int> idx;
  for (int i = 0; i < n; ++i) {
    Point3f c = test::randomPoint(rng, -4, 4);
    for (int k = 0; k < 3; ++k) {
      p.push_back(c + test::randomDirection(rng) * 0.8f);
      idx.push_back(3 * i + k);
    }
  }
  return std::make_unique<TriangleMesh>(t, false, idx, p);
}

void buildMixedScene(TestScene* s) {
  RNG rng(21);
  const TriangleMesh* ground = s->addMesh(terrain(16, Transform()));
  const TriangleMesh* tris = s->addMesh(soup(300, rng, rotateY(20)));
  s->addTriangles(ground, 0, ground->triangleCount());
  s->add(
      std::make_unique<SphereShape>(translate(Vector3f(1, 1, 1)), false, 1.2f, -1.2f, 1.2f, 360));
  s->add(std::make_unique<SphereShape>(translate(Vector3f(-2, 2, 0)) * rotateX(70), false, 1, -0.4f,
                                       0.8f, 250));  // partial
  s->addTriangles(tris, 0, 150);
  s->add(std::make_unique<SphereShape>(translate(Vector3f(2, -2, 1)) * scale(1, 2, 0.5f), true, 1,
                                       -1, 1, 360));  // an ellipsoid, inside out
  s->add(std::make_unique<SphereShape>(scale(-1, 1, 1) * translate(Vector3f(3, 3, -1)), false, 0.7f,
                                       -0.7f, 0.7f, 360));  // mirrored
  s->addTriangles(tris, 150, 300);  // the second run of the soup: a second Embree geometry
  for (int i = 0; i < 20; ++i) {
    Point3f c = test::randomPoint(rng, -5, 5);
    s->add(std::make_unique<SphereShape>(translate(Vector3f(c)), false, 0.3f, -0.3f, 0.3f, 360));
  }
}

TEST(EmbreeAggregate, Stats) {
  TestScene s;
  buildMixedScene(&s);
  EmbreeAggregate agg(test::embreeDevice(), s.primitives);
  AggregateStats st = agg.stats();
  EXPECT_EQ(st.name, "embree");
  EXPECT_EQ(st.counts["embree triangle geometries"], 3);
  EXPECT_EQ(st.counts["embree user geometries"], 1);
  EXPECT_EQ(st.counts["triangles"], 16 * 16 * 2 + 300);
  EXPECT_EQ(st.counts["user primitives"], 24);
  Bounds3f b = agg.worldBound();
  EXPECT_LE(b.pMin.x, -5);
  EXPECT_GE(b.pMax.x, 5);
}

TEST(EmbreeAggregate, AgreesWithBruteForce) {
  TestScene s;
  buildMixedScene(&s);
  EmbreeAggregate agg(test::embreeDevice(), s.primitives);
  RNG rng(22);
  const int n = 30000;
  int hits = 0, hitMismatch = 0, primMismatch = 0, tMismatch = 0, occMismatch = 0;
  double maxRelT = 0;
  for (int i = 0; i < n; ++i) {
    Point3f o = test::randomPoint(rng, -8, 8);
    Point3f target = test::randomPoint(rng, -5, 5);
    Vector3f d = (target - o) * lerp(rng.uniformFloat(), 0.1f, 3.f);
    Ray ray(o, d);
    Float tRef = 0;
    const Primitive* primRef = nullptr;
    bool refHit = s.bruteIntersect(ray, &tRef, &primRef);
    SurfaceInteraction isect;
    bool hit = agg.intersect(ray, &isect);
    if (hit != refHit) {
      ++hitMismatch;
      continue;
    }
    if (!hit) {
      EXPECT_EQ(ray.tMax, kInfinity);
      continue;
    }
    ++hits;
    if (isect.primitive != primRef) ++primMismatch;
    double rel = std::abs(double(ray.tMax) - tRef) / tRef;
    maxRelT = std::max(maxRelT, rel);
    if (rel > 1e-4) ++tMismatch;
    // The interaction belongs to that hit.
    Point3f pAt = Ray(o, d)(ray.tMax);
    EXPECT_LT(distance(pAt, isect.p), 1e-3f) << i;
    ASSERT_GE(isect.pError.x, 0);
    EXPECT_NEAR(isect.n.length(), 1, 1e-4);

    // Occlusion over a random part of the way to the hit and beyond it.
    Float tMax = tRef * lerp(rng.uniformFloat(), 0.5f, 1.5f);
    Ray seg(o, d, tMax);
    if (agg.intersectP(seg) != s.bruteIntersectP(seg)) ++occMismatch;
  }
  RecordProperty("hits", hits);
  std::printf("[ info ] %d rays, %d hits, max relative t difference %.3g\n", n, hits, maxRelT);
  EXPECT_GT(hits, n / 4);
  EXPECT_EQ(hitMismatch, 0);
  EXPECT_EQ(primMismatch, 0);
  EXPECT_EQ(tMismatch, 0);
  EXPECT_EQ(occMismatch, 0);
}

// A triangle hit's interaction is the hit shape's own, field for field, whether Embree's geometry
// reaches the vertices through the mesh (a run of triangles in the mesh's order, also one that
// starts inside the mesh) or through the primitive's shape (a run out of the mesh's order).
TEST(EmbreeAggregate, TriangleHitsAreTheirShapesInteractions) {
  TestScene s;
  const TriangleMesh* m = s.addMesh(terrain(12, Transform()));
  const int n = m->triangleCount();
  s.addTriangles(m, n / 3, n);  // in order, from triangle n / 3: through the mesh
  s.add(std::make_unique<SphereShape>(Transform(), false, 0.1f, -0.1f, 0.1f, 360));
  for (int i = n / 3 - 1; i >= 0; --i)  // out of order: through the shapes
    s.add(std::make_unique<TriangleShape>(m, i));
  EmbreeAggregate agg(test::embreeDevice(), s.primitives);
  RNG rng(31);
  int hits[2] = {0, 0};
  for (int i = 0; i < 20000; ++i) {
    Ray ray(test::randomPoint(rng, -6, 6) + Vector3f(0, 0, 6),
            test::randomPoint(rng, -5, 5) - Point3f(0, 0, 6) - Vector3f(0, 0, 2));
    Ray shapeRay = ray;
    SurfaceInteraction isect;
    if (!agg.intersect(ray, &isect)) continue;
    const auto* tri = dynamic_cast<const TriangleShape*>(isect.primitive->shape);
    if (!tri) continue;
    SurfaceInteraction own;
    Float t;
    ASSERT_TRUE(tri->intersect(shapeRay, &t, &own)) << i;
    ++hits[tri->index() < n / 3];
    ASSERT_EQ(isect.p, own.p) << i;
    ASSERT_EQ(isect.pError, own.pError) << i;
    ASSERT_EQ(isect.n, own.n) << i;
    ASSERT_EQ(isect.uv, own.uv) << i;
    ASSERT_EQ(isect.wo, own.wo) << i;
    ASSERT_EQ(isect.dpdu, own.dpdu) << i;
    ASSERT_EQ(isect.dpdv, own.dpdv) << i;
    ASSERT_EQ(isect.shading.n, own.shading.n) << i;
    ASSERT_EQ(isect.shading.dpdu, own.shading.dpdu) << i;
    ASSERT_EQ(isect.shading.dndu, own.shading.dndu) << i;
  }
  std::printf("[ info ] hits through the mesh %d, through the shapes %d\n", hits[0], hits[1]);
  EXPECT_GT(hits[0], 5000);
  EXPECT_GT(hits[1], 2000);
}

TEST(EmbreeAggregate, HitsPointIntoThePrimitiveVector) {
  TestScene s;
  const TriangleMesh* m = s.addMesh(terrain(2, Transform()));
  s.add(std::make_unique<SphereShape>(Transform(), false, 1, -1, 1, 360));
  s.addTriangles(m, 0, m->triangleCount());
  EmbreeAggregate agg(test::embreeDevice(), s.primitives);
  SurfaceInteraction isect;
  Ray down(Point3f(0.1f, 0.2f, 5), Vector3f(0, 0, -1));
  ASSERT_TRUE(agg.intersect(down, &isect));
  EXPECT_EQ(isect.primitive, &s.primitives[0]);  // the sphere
  EXPECT_NEAR(down.tMax, 5 - std::sqrt(1 - 0.05f), 1e-5);
  Ray beside(Point3f(3.1f, 0.2f, 5), Vector3f(0, 0, -1));
  ASSERT_TRUE(agg.intersect(beside, &isect));
  EXPECT_GE(isect.primitive, &s.primitives[1]);
  EXPECT_LT(isect.primitive, s.primitives.data() + s.primitives.size());
  EXPECT_STREQ(isect.primitive->shape->kind(), "triangle");
  EXPECT_NEAR(isect.p.z, -2, 0.5f);
  EXPECT_NEAR(distance(isect.p, beside(beside.tMax)), 0, 1e-5f);
}

TEST(EmbreeAggregate, BadRaysMiss) {
  TestScene s;
  buildMixedScene(&s);
  EmbreeAggregate agg(test::embreeDevice(), s.primitives);
  Float nan = std::numeric_limits<Float>::quiet_NaN(), inf = kInfinity;
  std::vector<Ray> rays = {
      Ray(Point3f(nan, 0, 0), Vector3f(0, 0, 1)),     Ray(Point3f(0, 0, 10), Vector3f(0, nan, -1)),
      Ray(Point3f(0, 0, inf), Vector3f(0, 0, -1)),    Ray(Point3f(0, 0, 10), Vector3f(0, 0, -inf)),
      Ray(Point3f(-inf, 0, 0), Vector3f(1, 0, 0)),    Ray(Point3f(0, 0, 10), Vector3f(0, 0, 0)),
      Ray(Point3f(0, 0, 10), Vector3f(0, 0, -1), nan)};
  for (const Ray& r : rays) {
    SurfaceInteraction isect;
    EXPECT_FALSE(agg.intersect(r, &isect));
    EXPECT_FALSE(agg.intersectP(r));
  }
  EmbreeAggregate empty(test::embreeDevice(), std::vector<Primitive>());
  SurfaceInteraction isect;
  EXPECT_FALSE(empty.intersect(Ray(Point3f(), Vector3f(0, 0, 1)), &isect));
  EXPECT_TRUE(empty.worldBound().empty());
}

TEST(EmbreeAggregate, DeviceErrorsBecomeExceptions) {
  EXPECT_EQ(test::embreeDevice().config(), "isa=avx2");
  EXPECT_THROW(EmbreeDevice("isa=avx2,threads=abc"), EmbreeError);
}

// A renderer thread with flush-to-zero set finds the same hits as one without.
TEST(EmbreeAggregate, FlushToZeroKeepsResults) {
  TestScene s;
  buildMixedScene(&s);
  EmbreeAggregate agg(test::embreeDevice(), s.primitives);
  auto trace = [&](std::vector<Float>* ts, std::vector<const Primitive*>* prims) {
    RNG rng(51);
    for (int i = 0; i < 3000; ++i) {
      Point3f o = test::randomPoint(rng, -8, 8);
      Ray ray(o, test::randomPoint(rng, -5, 5) - o);
      SurfaceInteraction isect;
      bool hit = agg.intersect(ray, &isect);
      ts->push_back(hit ? ray.tMax : -1);
      prims->push_back(hit ? isect.primitive : nullptr);
    }
  };
  std::vector<Float> t0, t1;
  std::vector<const Primitive*> p0, p1;
  trace(&t0, &p0);
  std::thread worker([&] {
    enableFlushToZero();
    trace(&t1, &p1);
  });
  worker.join();
  EXPECT_EQ(t0, t1);
  EXPECT_EQ(p0, p1);
}

// For each placement of the geometry, rays from outside hit it; from every hit, rays spawned in
// random directions must not hit the same primitive again (on the side they arrived from for the
// convex sphere, on both sides for a flat triangle), and rays spawned into the sphere reach its
// far side, never the point they left.
struct Placement {
  const char* name;
  Transform t;
  Float scale;
  bool resolvable;  // geometry much larger than the float spacing at its position
};

TEST(EmbreeAggregate, SpawnedRaysDoNotReHit) {
  Vector3f far(1e5f, 1e5f, 1e5f);
  std::vector<Placement> placements = {
      {"origin", Transform(), 1, true},
      {"far", translate(far), 1, true},
      {"tiny", scale(1e-4f, 1e-4f, 1e-4f), 1e-4f, true},
      {"huge", scale(1e4f, 1e4f, 1e4f), 1e4f, true},
      {"far huge", translate(far) * scale(1e4f, 1e4f, 1e4f), 1e4f, true},
      {"far tiny", translate(far) * scale(1e-4f, 1e-4f, 1e-4f), 1e-4f, false},
      {"far rotated", translate(far) * rotate(37, Vector3f(1, -2, 0.5f)) * scale(3, 3, 3), 3, true},
  };
  for (const Placement& pl : placements) {
    TestScene s;
    RNG rng(31);
    const TriangleMesh* mesh = s.addMesh(soup(40, rng, pl.t));
    s.add(std::make_unique<SphereShape>(pl.t, false, 1, -1, 1, 360));
    s.addTriangles(mesh, 0, mesh->triangleCount());
    EmbreeAggregate agg(test::embreeDevice(), s.primitives);
    int hits = 0, spawned = 0, reHits = 0, shortExits = 0, bruteReHits = 0;
    for (int i = 0; i < 4000; ++i) {
      // Object space: from a sphere of radius 8 toward the geometry.
      Point3f oObj = Point3f(test::randomDirection(rng) * 8);
      Point3f target = test::randomPoint(rng, -1.5f, 1.5f);
      Ray ray = pl.t(Ray(oObj, target - oObj));
      SurfaceInteraction isect;
      if (!agg.intersect(ray, &isect)) continue;
      ++hits;
      bool isSphere = isect.primitive == &s.primitives[0];
      Normal3f nf = faceForward(isect.n, isect.wo);
      for (int k = 0; k < 8; ++k) {
        // The side the ray came from; for a flat triangle either side.
        Vector3f w = test::randomDirection(rng);
        if (isSphere && dot(w, nf) < 0) w = -w;
        Ray out = isect.spawnRay(w);
        SurfaceInteraction next;
        ++spawned;
        Float t;
        if (isect.primitive->shape->intersect(out, &t, nullptr)) ++bruteReHits;
        if (agg.intersect(out, &next) && next.primitive == isect.primitive) ++reHits;
        // Into the sphere from outside, at least 0.1 off the tangent plane: the chord is at
        // least 0.2 r long.
        if (isSphere && dot(isect.wo, isect.n) > 0) {
          Vector3f in = -w;
          if (dot(in, isect.n) > -0.1f) continue;
          Ray inRay = isect.spawnRay(in);
          if (!agg.intersect(inRay, &next) || next.primitive != isect.primitive ||
              inRay.tMax * in.length() < 0.19f * pl.scale)
            ++shortExits;
        }
      }
    }
    SCOPED_TRACE(pl.name);
    std::printf(
        "[ info ] %-12s %d hits, %d spawned rays: %d re-hits (brute force %d), %d bad "
        "exits\n",
        pl.name, hits, spawned, reHits, bruteReHits, shortExits);
    if (pl.resolvable) {
      EXPECT_GT(hits, 1500);
      EXPECT_EQ(shortExits, 0);
    }
    EXPECT_EQ(reHits, 0);
    EXPECT_EQ(bruteReHits, 0);
  }
}

// Large triangles hit far from their vertices (Embree's t has an error proportional to the
// distance to the vertices, not to the hit point), and an axis-aligned plane, where the spawned
// origin's offset along the normal is zero and Embree computes t = 0 exactly.
TEST(EmbreeAggregate, LargeAndAxisAlignedTrianglesAreNotReHit) {
  std::vector<Transform> placements = {Transform(), rotate(3, Vector3f(1, 1, 0)),
                                       rotate(41, Vector3f(-1, 2, 5)),
                                       translate(Vector3f(0.3f, -7, 2)) * rotateY(89.9f)};
  for (const Transform& t : placements) {
    TestScene s;
    const TriangleMesh* m = s.addMesh(std::make_unique<TriangleMesh>(
        t, false, std::vector<int>{0, 1, 2, 0, 2, 3},
        std::vector<Point3f>{
            {-1000, -1000, 0}, {1000, -1000, 0}, {1000, 1000, 0}, {-1000, 1000, 0}}));
    s.addTriangles(m, 0, 2);
    EmbreeAggregate agg(test::embreeDevice(), s.primitives);
    RNG rng(41);
    int hits = 0, reHits = 0, bruteReHits = 0, occluded = 0;
    for (int i = 0; i < 5000; ++i) {
      // Near the middle of the quad, from either side.
      Point3f target(lerp(rng.uniformFloat(), -3.f, 3.f), lerp(rng.uniformFloat(), -3.f, 3.f), 0);
      Point3f o = target + test::randomDirection(rng) * lerp(rng.uniformFloat(), 0.01f, 100.f);
      Ray ray = t(Ray(o, target - o));
      SurfaceInteraction isect;
      if (!agg.intersect(ray, &isect)) continue;
      ++hits;
      for (int k = 0; k < 4; ++k) {
        Vector3f w = test::randomDirection(rng);  // both sides: a flat triangle is never hit again
        Ray out = isect.spawnRay(w);
        Float tHit;
        if (isect.primitive->shape->intersect(out, &tHit, nullptr)) ++bruteReHits;
        if (agg.intersectP(out)) ++occluded;  // nothing else is there
        SurfaceInteraction next;
        if (agg.intersect(out, &next) && next.primitive == isect.primitive) ++reHits;
      }
    }
    std::printf("[ info ] big quad: %d hits, %d re-hits (brute force %d), %d occluded\n", hits,
                reHits, bruteReHits, occluded);
    EXPECT_GT(hits, 4000);
    EXPECT_EQ(occluded, 0);
    EXPECT_EQ(reHits, 0);
    EXPECT_EQ(bruteReHits, 0);
  }
}

// Without user geometry Embree traces the groups as packets; each ray gets the hit intersect
// gives it, to the bit (the interaction is computed from the ray and the triangle, not from
// Embree's barycentrics; a tie between two surfaces could go either way, and random rays meet
// none). A mesh with a degenerate triangle has Embree's filter callback, which takes packets.
TEST(EmbreeAggregate, CoherentRaysAsPacketsGetTheHitsOfSingleRays) {
  TestScene s;
  RNG rng(31);
  const TriangleMesh* ground = s.addMesh(terrain(16, Transform()));
  const TriangleMesh* tris = s.addMesh(soup(300, rng, rotateY(20)));
  std::vector<Point3f> p = {{-1, -1, 3}, {1, -1, 3}, {0, 1, 3.5f}, {2, 2, 2}, {2, 2, 2}};
  const TriangleMesh* withDegenerate = s.addMesh(
      std::make_unique<TriangleMesh>(Transform(), false, std::vector<int>{0, 1, 2, 3, 4, 3}, p));
  s.addTriangles(ground, 0, ground->triangleCount());
  s.addTriangles(tris, 0, 300);
  s.addTriangles(withDegenerate, 0, 2);
  EmbreeAggregate agg(test::embreeDevice(), s.primitives);
  EXPECT_TRUE(agg.tracesCoherentRaysFaster());
  test::CoherentFigures f = test::compareCoherent(agg, 32, 6000);
  EXPECT_GT(f.hits, f.rays / 3);
  test::expectTheSameHits(f);
}

// With user geometry (the quadrics) the callbacks take one ray at a time: the rays are traced one
// by one, the same hits.
TEST(EmbreeAggregate, CoherentRaysWithUserGeometryAreTracedOneByOne) {
  TestScene s;
  buildMixedScene(&s);
  EmbreeAggregate agg(test::embreeDevice(), s.primitives);
  EXPECT_FALSE(agg.tracesCoherentRaysFaster());
  test::CoherentFigures f = test::compareCoherent(agg, 33, 2000);
  EXPECT_GT(f.hits, f.rays / 3);
  test::expectTheSameHits(f);
}

}  // namespace
}  // namespace candela
