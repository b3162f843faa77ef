// Object instances on Embree (lrt draft §4.1.2): static instances agree hit for hit with the same
// shapes created in world space, report the prototype's primitive and a world-space interaction;
// animated instances (pbrt 2e §2.9.3) agree, at each ray time, with a static instance under the
// interpolated transform; rays spawned from instanced hits never re-hit the surface they leave.
#include <gtest/gtest.h>

#include <cstdio>

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

// A shape of a prototype, in the prototype's space, that can also be made under any transform.
struct ShapeSpec {
  enum Kind { Sphere, Soup } kind;
  Transform toPrototype;
  Float radius = 1, zMin = -1, zMax = 1, phiMax = 360;  // sphere
  uint64_t seed = 0;                                    // soup of 30 triangles
  bool reverse = false;
};

// Shapes under a transform, with their primitives in the order of the specs.
struct Built {
  std::vector<std::unique_ptr<TriangleMesh>> meshes;
  std::vector<std::unique_ptr<Shape>> shapes;
};

void build(const std::vector<ShapeSpec>& specs, const Transform& t, Built* out,
           std::vector<Primitive>* prims) {
  for (const ShapeSpec& s : specs) {
    Transform x = t * s.toPrototype;
    if (s.kind == ShapeSpec::Sphere) {
      out->shapes.push_back(
          std::make_unique<SphereShape>(x, s.reverse, s.radius, s.zMin, s.zMax, s.phiMax));
      prims->push_back(Primitive{out->shapes.back().get(), nullptr, nullptr});
      continue;
    }
    RNG rng(s.seed);
    std::vector<Point3f> p;
    std::vector<int> idx;
    for (int i = 0; i < 30; ++i) {
      Point3f c = test::randomPoint(rng, -1.5f, 1.5f);
      for (int k = 0; k < 3; ++k) {
        p.push_back(c + test::randomDirection(rng) * 0.6f);
        idx.push_back(3 * i + k);
      }
    }
    out->meshes.push_back(std::make_unique<TriangleMesh>(x, s.reverse, idx, p));
    for (auto& tri : createTriangleShapes(out->meshes.back().get())) {
      prims->push_back(Primitive{tri.get(), nullptr, nullptr});
      out->shapes.push_back(std::move(tri));
    }
  }
}

std::vector<ShapeSpec> prototypeA() {
  ShapeSpec full{ShapeSpec::Sphere, translate(Vector3f(0.5f, 0, 0))};
  ShapeSpec partial{ShapeSpec::Sphere, translate(Vector3f(-1, 1, 0)) * rotateX(60)};
  partial.radius = 0.8f, partial.zMin = -0.3f, partial.zMax = 0.7f, partial.phiMax = 230;
  ShapeSpec soup{ShapeSpec::Soup, rotateZ(15)};
  soup.seed = 5;
  return {full, partial, soup};
}
std::vector<ShapeSpec> prototypeB() {
  ShapeSpec soup{ShapeSpec::Soup, Transform()};
  soup.seed = 9;
  ShapeSpec ellipsoid{ShapeSpec::Sphere, scale(1, 0.5f, 2)};
  ellipsoid.reverse = true;
  return {soup, ellipsoid};
}

std::vector<Transform> placementsA() {
  return {translate(Vector3f(-4, 0, 0)), translate(Vector3f(4, 1, -1)) * rotateY(70),
          translate(Vector3f(0, 4, 2)) * scale(1.5f, 1.5f, 1.5f),
          translate(Vector3f(0, -4, 0)) * scale(-1, 1, 1),  // mirrored
          translate(Vector3f(0, 0, 5)) * rotate(33, Vector3f(1, 2, 3)) * scale(2, 0.7f, 1)};
}
std::vector<Transform> placementsB() {
  return {Transform(), translate(Vector3f(3, -3, 3)) * rotateX(-40),
          translate(Vector3f(-3, 3, -3)) * scale(0.5f, 0.5f, 0.5f)};
}

// The same geometry twice: as prototypes with instances, and flattened into world space.
struct TwoScenes {
  SceneGeometry geometry;
  Built protoShapes, worldShapes, flatShapes;
  std::vector<Primitive> flat;
  std::vector<const Primitive*> flatToProto;  // flat[i] is an instance of *flatToProto[i]

  // trianglesOnly: the prototypes without their spheres (no user geometry anywhere).
  explicit TwoScenes(bool trianglesOnly = false) : trianglesOnly_(trianglesOnly) {
    ShapeSpec ground{ShapeSpec::Soup, translate(Vector3f(0, 0, -6)) * scale(4, 4, 0.3f)};
    ground.seed = 77;
    build({ground}, Transform(), &worldShapes, &geometry.primitives);
    build({ground}, Transform(), &flatShapes, &flat);
    for (const Primitive& p : geometry.primitives) flatToProto.push_back(&p);
    addPrototype("A", prototypeA(), placementsA());
    addPrototype("B", prototypeB(), placementsB());
  }
  void addPrototype(const char* name, std::vector<ShapeSpec> specs,
                    const std::vector<Transform>& placements) {
    if (trianglesOnly_)
      std::erase_if(specs, [](const ShapeSpec& s) { return s.kind == ShapeSpec::Sphere; });
    auto proto = std::make_unique<InstancePrototype>();
    proto->name = name;
    build(specs, Transform(), &protoShapes, &proto->primitives);
    for (const Transform& t : placements) {
      geometry.instances.push_back(Instance{proto.get(), AnimatedTransform(t)});
      size_t first = flat.size();
      build(specs, t, &flatShapes, &flat);
      for (size_t i = first; i < flat.size(); ++i)
        flatToProto.push_back(&proto->primitives[i - first]);
    }
    geometry.prototypes.push_back(std::move(proto));
  }
  bool trianglesOnly_;
};

TEST(EmbreeInstances, StatsCountInstancesAndSharedPrototypes) {
  TwoScenes s;
  EmbreeAggregate agg(test::embreeDevice(), s.geometry);
  AggregateStats st = agg.stats();
  EXPECT_EQ(st.counts["instances"], 8);
  EXPECT_EQ(st.counts["prototypes"], 2);
  EXPECT_EQ(st.counts["embree instance geometries"], 8);
  EXPECT_EQ(st.counts["motion instances"], 0);
  EXPECT_EQ(st.counts["triangles"], 30);            // the ground only
  EXPECT_EQ(st.counts["prototype triangles"], 60);  // one soup per prototype, once
  EXPECT_EQ(st.counts["prototype user primitives"], 3);
  EmbreeAggregate flat(test::embreeDevice(), s.flat);
  // Instances are bounded by their prototype's box transformed: at least the flat bound.
  Bounds3f a = agg.worldBound(), b = flat.worldBound();
  EXPECT_TRUE(a.inside(b.pMin) && a.inside(b.pMax));
}

TEST(EmbreeInstances, AgreeWithFlattenedShapes) {
  TwoScenes s;
  EmbreeAggregate agg(test::embreeDevice(), s.geometry);
  EmbreeAggregate flat(test::embreeDevice(), s.flat);
  RNG rng(3);
  const int n = 40000;
  int hits = 0, hitMismatch = 0, primMismatch = 0, tMismatch = 0, occMismatch = 0;
  double maxRelT = 0, maxP = 0, minNormalDot = 1;
  for (int i = 0; i < n; ++i) {
    Point3f o = test::randomPoint(rng, -10, 10);
    Vector3f d = (test::randomPoint(rng, -6, 6) - o) * lerp(rng.uniformFloat(), 0.1f, 3.f);
    Ray r1(o, d), r2(o, d);
    SurfaceInteraction a, b;
    bool h1 = agg.intersect(r1, &a), h2 = flat.intersect(r2, &b);
    if (h1 != h2) {
      ++hitMismatch;
      continue;
    }
    Float tOcc = (h1 ? r2.tMax : 10.f) * lerp(rng.uniformFloat(), 0.5f, 1.5f);
    if (agg.intersectP(Ray(o, d, tOcc)) != flat.intersectP(Ray(o, d, tOcc))) ++occMismatch;
    if (!h1) continue;
    ++hits;
    size_t fi = size_t(b.primitive - s.flat.data());
    if (a.primitive != s.flatToProto[fi]) ++primMismatch;
    double rel = std::abs(double(r1.tMax) - r2.tMax) / r2.tMax;
    maxRelT = std::max(maxRelT, rel);
    // Relative to the distance, but a hit a few float steps from the origin (t ~ 1e-5) differs
    // by the rounding of the ray in the instance's space: within the points' error bounds.
    double apart = std::abs(double(r1.tMax) - r2.tMax) * d.length();
    if (rel > 1e-4 && apart > a.pError.length() + b.pError.length()) ++tMismatch;
    maxP = std::max(maxP, double(distance(a.p, b.p)));
    minNormalDot = std::min(minNormalDot, double(dot(a.n, b.n)));
    EXPECT_NEAR(a.n.length(), 1, 1e-4);
    EXPECT_NEAR(dot(a.wo, b.wo), 1, 1e-6);
    // The point's error bound covers the hit point of the world ray.
    Point3f onRay = Ray(o, d)(r1.tMax);
    for (int k = 0; k < 3; ++k)
      EXPECT_LE(std::abs(a.p[k] - onRay[k]), a.pError[k] + 1e-3f * std::abs(d[k]) * r1.tMax);
  }
  std::printf(
      "[ info ] %d rays, %d hits; mismatches: hit %d, primitive %d, t %d, occlusion %d; max "
      "relative t difference %.3g, max |p - p_flat| %.3g, min n.n_flat %.8f\n",
      n, hits, hitMismatch, primMismatch, tMismatch, occMismatch, maxRelT, maxP, minNormalDot);
  EXPECT_GT(hits, n / 5);
  EXPECT_EQ(hitMismatch, 0);
  EXPECT_EQ(primMismatch, 0);
  EXPECT_EQ(tMismatch, 0);
  EXPECT_EQ(occMismatch, 0);
  EXPECT_LT(maxP, 1e-3);
  EXPECT_GT(minNormalDot, 0.9999);
}

// Rays in groups (as a pixel's camera rays) into static instances of triangle prototypes, traced
// as Embree packets, get the hits intersect gives them one at a time, to the bit; with spheres
// in the prototypes (user geometry) the rays go one at a time.
TEST(EmbreeInstances, CoherentRaysGetTheHitsOfSingleRays) {
  for (bool trianglesOnly : {true, false}) {
    SCOPED_TRACE(trianglesOnly ? "triangles" : "triangles and spheres");
    TwoScenes s(trianglesOnly);
    EmbreeAggregate agg(test::embreeDevice(), s.geometry);
    EXPECT_EQ(agg.tracesCoherentRaysFaster(), trianglesOnly);
    test::CoherentFigures f = test::compareCoherent(agg, 4, 4000);
    EXPECT_GT(f.hits, f.rays / 5);
    test::expectTheSameHits(f);
  }
}

// One animated instance of prototype A against, at each of a few times, a static instance under
// the transform interpolated at that time.
TEST(EmbreeInstances, AnimatedInstanceMatchesStaticInstanceAtEachTime) {
  Built shapes;
  InstancePrototype proto;
  build(prototypeA(), Transform(), &shapes, &proto.primitives);
  Transform t0 = translate(Vector3f(-2, 0, 0)) * rotateZ(-30);
  Transform t1 =
      translate(Vector3f(2, 1, 0.5f)) * rotate(80, Vector3f(1, 1, 0)) * scale(1.2f, 1, 1);
  SceneGeometry moving;
  moving.instances.push_back(Instance{&proto, AnimatedTransform(t0, 0, t1, 2)});
  EmbreeAggregate agg(test::embreeDevice(), moving);
  AggregateStats st = agg.stats();
  EXPECT_EQ(st.counts["motion instances"], 1);
  EXPECT_EQ(st.counts["embree motion user geometries"], 1);
  EXPECT_EQ(st.counts["embree instance geometries"], 0);
  EXPECT_EQ(st.counts["prototypes"], 1);

  RNG rng(8);
  int hits = 0, hitMismatch = 0, primMismatch = 0, tMismatch = 0, occMismatch = 0;
  for (Float time : {0.f, 0.3f, 1.f, 1.7f, 2.f}) {
    SceneGeometry still;
    still.instances.push_back(
        Instance{&proto, AnimatedTransform(moving.instances[0].instanceToWorld.interpolate(time))});
    EmbreeAggregate ref(test::embreeDevice(), still);
    for (int i = 0; i < 5000; ++i) {
      Point3f o = test::randomPoint(rng, -8, 8);
      Vector3f d = test::randomPoint(rng, -3, 3) - o;
      Ray r1(o, d, kInfinity, time), r2(o, d, kInfinity, time);
      SurfaceInteraction a, b;
      bool h1 = agg.intersect(r1, &a), h2 = ref.intersect(r2, &b);
      if (agg.intersectP(Ray(o, d, kInfinity, time)) != h1) ++occMismatch;
      if (h1 != h2) {
        ++hitMismatch;
        continue;
      }
      if (!h1) continue;
      ++hits;
      if (a.primitive != b.primitive) ++primMismatch;
      if (std::abs(r1.tMax - r2.tMax) > 1e-4f * r2.tMax) ++tMismatch;
      EXPECT_LT(distance(a.p, b.p), 1e-3f);
      EXPECT_GT(dot(a.n, b.n), 0.9999f);
      EXPECT_EQ(a.time, time);
    }
  }
  std::printf("[ info ] %d hits; mismatches: hit %d, primitive %d, t %d, occlusion %d\n", hits,
              hitMismatch, primMismatch, tMismatch, occMismatch);
  EXPECT_GT(hits, 3000);
  EXPECT_EQ(hitMismatch, 0);
  EXPECT_EQ(primMismatch, 0);
  EXPECT_EQ(tMismatch, 0);
  EXPECT_EQ(occMismatch, 0);
  // The aggregate's bound holds the prototype's bound all along the sweep.
  Bounds3f b = agg.worldBound();
  Bounds3f protoBound = EmbreeAggregate(test::embreeDevice(), proto.primitives).worldBound();
  for (int k = 0; k <= 200; ++k) {
    Bounds3f at = moving.instances[0].instanceToWorld.interpolate(k / 100.f)(protoBound);
    for (int c = 0; c < 8; ++c) EXPECT_TRUE(b.inside(at.corner(c))) << k;
  }
}

TEST(EmbreeInstances, EmptyAndUnusedPrototypesBuildNothing) {
  SceneGeometry g;
  g.prototypes.push_back(std::make_unique<InstancePrototype>());  // empty, used
  g.prototypes.push_back(std::make_unique<InstancePrototype>());  // unused
  Built shapes;
  build(prototypeB(), Transform(), &shapes, &g.prototypes[1]->primitives);
  g.instances.push_back(Instance{g.prototypes[0].get(), AnimatedTransform()});
  EmbreeAggregate agg(test::embreeDevice(), g);
  AggregateStats st = agg.stats();
  EXPECT_EQ(st.counts["prototypes"], 0);
  SurfaceInteraction isect;
  EXPECT_FALSE(agg.intersect(Ray(Point3f(0, 0, 10), Vector3f(0, 0, -1)), &isect));
  EXPECT_TRUE(agg.worldBound().empty());
}

// From hits on instanced surfaces (static and animated, near the origin, far away, tiny and
// huge), spawned rays never hit the same primitive again on the side they leave from.
TEST(EmbreeInstances, SpawnedRaysDoNotReHit) {
  Vector3f far(1e5f, 1e5f, 1e5f);
  struct Case {
    const char* name;
    Transform t;
    bool animated;
  };
  std::vector<Case> cases = {
      {"origin", rotate(20, Vector3f(1, 2, 3)), false},
      {"far", translate(far) * rotateX(30), false},
      {"tiny", scale(1e-4f, 1e-4f, 1e-4f), false},
      {"huge", scale(1e4f, 1e4f, 1e4f) * rotateY(10), false},
      {"mirrored", scale(-2, 1, 1), false},
      {"animated", translate(Vector3f(1, 2, 3)), true},
      {"far animated", translate(far) * scale(3, 3, 3), true},
  };
  for (const Case& c : cases) {
    Built shapes;
    InstancePrototype proto;
    ShapeSpec sphere{ShapeSpec::Sphere, Transform()};
    ShapeSpec soup{ShapeSpec::Soup, Transform()};
    soup.seed = 4;
    build({sphere, soup}, Transform(), &shapes, &proto.primitives);
    SceneGeometry g;
    AnimatedTransform xf =
        c.animated ? AnimatedTransform(c.t, 0, c.t * rotateZ(40), 1) : AnimatedTransform(c.t);
    g.instances.push_back(Instance{&proto, xf});
    EmbreeAggregate agg(test::embreeDevice(), g);
    RNG rng(12);
    int hits = 0, spawned = 0, reHits = 0;
    for (int i = 0; i < 3000; ++i) {
      Float time = rng.uniformFloat();
      Transform at = xf.interpolate(time);
      Point3f oObj = Point3f(test::randomDirection(rng) * 6);
      Ray objRay(oObj, test::randomPoint(rng, -1.5f, 1.5f) - oObj);
      Ray ray(at(objRay.o), at(objRay.d), kInfinity, time);
      SurfaceInteraction isect;
      if (!agg.intersect(ray, &isect)) continue;
      ++hits;
      bool isSphere = isect.primitive == &proto.primitives[0];
      Normal3f nf = faceForward(isect.n, isect.wo);
      for (int k = 0; k < 6; ++k) {
        Vector3f w = test::randomDirection(rng);
        if (isSphere && dot(w, nf) < 0) w = -w;
        Ray out = isect.spawnRay(w);
        SurfaceInteraction next;
        ++spawned;
        if (agg.intersect(out, &next) && next.primitive == isect.primitive) ++reHits;
      }
    }
    std::printf("[ info ] %-13s %d hits, %d spawned rays, %d re-hits\n", c.name, hits, spawned,
                reHits);
    SCOPED_TRACE(c.name);
    EXPECT_GT(hits, 1000);
    EXPECT_EQ(reHits, 0);
  }
}

}  // namespace
}  // namespace candela
