// The reference aggregates (bvh, kdtree, grid) on small scenes with known answers: the factory's
// names and parameters, the draft's grid resolution and kd-tree depth rules, hits and misses,
// rays the aggregates must refuse, rays lying in voxel faces and split planes, instances (static,
// mirrored, animated) and concurrent queries.
#include <gtest/gtest.h>

#include <thread>

#include "accel/aggregate_factory.h"
#include "accel/bvh/bvh_aggregate.h"
#include "accel/embree/embree_device.h"
#include "accel/grid/grid_aggregate.h"
#include "accel/kdtree/kdtree_aggregate.h"
#include "core/rng.h"
#include "shapes/sphere.h"
#include "shapes/triangle_mesh.h"
#include "support/param_items.h"
#include "support/test_device.h"

namespace candela {
namespace {

// Shapes kept alive for a SceneGeometry that refers to them.
struct Scene {
  std::vector<std::unique_ptr<TriangleMesh>> meshes;
  std::vector<std::unique_ptr<Shape>> shapes;
  SceneGeometry geometry;

  const Primitive& addSphere(const Transform& t, Float r, std::vector<Primitive>* out) {
    shapes.push_back(std::make_unique<SphereShape>(t, false, r, -r, r, 360));
    out->push_back(Primitive{shapes.back().get(), nullptr, nullptr});
    return out->back();
  }
  // An n x n grid of unit squares in the plane z = z0, corners at integer x, y in [0, n].
  void addFloor(int n, Float z0, std::vector<Primitive>* out) {
    std::vector<Point3f> p;
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) p.emplace_back(Float(i), Float(j), z0);
    std::vector<int> idx;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        int v = j * (n + 1) + i;
        idx.insert(idx.end(), {v, v + 1, v + n + 2, v, v + n + 2, v + n + 1});
      }
    meshes.push_back(std::make_unique<TriangleMesh>(Transform(), false, idx, p));
    for (auto& s : createTriangleShapes(meshes.back().get())) {
      out->push_back(Primitive{s.get(), nullptr, nullptr});
      shapes.push_back(std::move(s));
    }
  }
  InstancePrototype* addPrototype(const std::string& name) {
    geometry.prototypes.push_back(std::make_unique<InstancePrototype>());
    geometry.prototypes.back()->name = name;
    return geometry.prototypes.back().get();
  }
};

std::unique_ptr<Aggregate> make(const std::string& kind, const SceneGeometry& g,
                                const ParamSet& params = {}) {
  return createAggregate(kind, params, g, test::embreeDevice(), FileLoc{"test.pbrt", 3, 1});
}

// --- Factory -------------------------------------------------------------------------------

TEST(AggregateFactory, NamesAndDefault) {
  EXPECT_EQ(acceleratorNames(), (std::vector<std::string>{"embree", "bvh", "kdtree", "grid"}));
  SceneGeometry g;
  EXPECT_EQ(make("", g)->stats().name, "embree");
  for (const std::string& n : acceleratorNames()) EXPECT_EQ(make(n, g)->stats().name, n);
}

TEST(AggregateFactory, UnknownNameListsTheKnownOnes) {
  SceneGeometry g;
  try {
    make("octree", g);
    FAIL() << "no error";
  } catch (const SceneError& e) {
    std::string m = e.what();
    EXPECT_NE(m.find("test.pbrt:3:1"), std::string::npos) << m;
    EXPECT_NE(m.find("'octree'"), std::string::npos) << m;
    EXPECT_NE(m.find("embree, bvh, kdtree, grid"), std::string::npos) << m;
  }
}

TEST(AggregateFactory, BadParametersAreSceneErrors) {
  SceneGeometry g;
  ParamSet a;
  a.add(test::strings("splitmethod", {"octant"}));
  EXPECT_THROW(make("bvh", g, a), SceneError);
  ParamSet b;
  b.add(test::floats("emptybonus", {1.5f}));
  EXPECT_THROW(make("kdtree", g, b), SceneError);
  ParamSet c;
  c.add(test::ints("maxprims", {0}));
  EXPECT_THROW(make("kdtree", g, c), SceneError);
  ParamSet d;
  d.add(test::ints("maxnodeprims", {0}));
  EXPECT_THROW(make("bvh", g, d), SceneError);
}

TEST(AggregateFactory, ParametersAreReadAndUsed) {
  Scene s;
  RNG rng(5);
  for (int i = 0; i < 200; ++i) {
    Vector3f c(rng.uniformFloat() * 20, rng.uniformFloat() * 20, rng.uniformFloat() * 20);
    s.addSphere(translate(c), 0.2f, &s.geometry.primitives);
  }
  // The draft's App. C types emptybonus "integer"; it is accepted, and every item is used.
  ParamSet k;
  k.add(test::ints("emptybonus", {0}));
  k.add(test::ints("maxdepth", {3}));
  k.add(test::ints("intersectcost", {80}));
  auto kd = make("kdtree", s.geometry, k);
  EXPECT_LE(kd->stats().counts["max depth"], 3);
  int unused = 0;
  k.forEachUnused([&](const ParamItem&) { ++unused; });
  EXPECT_EQ(unused, 0);

  ParamSet b;
  b.add(test::ints("maxnodeprims", {50}));
  b.add(test::strings("splitmethod", {"equal"}));
  auto bvh = make("bvh", s.geometry, b);
  // 200 items halved until at most 50 remain: 7 nodes.
  EXPECT_EQ(bvh->stats().counts["nodes"], 7);

  ParamSet gp;
  gp.add(test::ints("refineimmediately", {1}));
  make("grid", s.geometry, gp);
  unused = 0;
  gp.forEachUnused([&](const ParamItem&) { ++unused; });
  EXPECT_EQ(unused, 0);
}

// --- The draft's rules ---------------------------------------------------------------------

TEST(GridAggregate, ResolutionRule) {
  // 3 N^(1/3) voxels along the longest axis, the others in proportion, each in [1, 64].
  Bounds3f b(Point3f(0, 0, 0), Point3f(10, 5, 1));
  EXPECT_EQ(GridAggregate::resolution(b, 1000), (std::array<int, 3>{30, 15, 3}));
  EXPECT_EQ(GridAggregate::resolution(b, 1000000), (std::array<int, 3>{64, 64, 30}));
  EXPECT_EQ(GridAggregate::resolution(b, 1), (std::array<int, 3>{3, 2, 1}));  // 1.5 rounds to 2
  Bounds3f flat(Point3f(0, 0, 0), Point3f(4, 4, 0));
  EXPECT_EQ(GridAggregate::resolution(flat, 64), (std::array<int, 3>{12, 12, 1}));
  EXPECT_EQ(GridAggregate::resolution(Bounds3f(Point3f(1, 1, 1)), 10),
            (std::array<int, 3>{1, 1, 1}));
  EXPECT_EQ(GridAggregate::resolution(Bounds3f(), 0), (std::array<int, 3>{1, 1, 1}));
}

TEST(KdTreeAggregate, DepthLimitRule) {
  EXPECT_EQ(KdTreeAggregate::depthLimit(1, -1), 8);
  EXPECT_EQ(KdTreeAggregate::depthLimit(1024, -1), 21);    // 8 + 13
  EXPECT_EQ(KdTreeAggregate::depthLimit(1000000, 0), 33);  // 8 + 1.3 * 19 = 32.7
  EXPECT_EQ(KdTreeAggregate::depthLimit(1000000, 5), 5);
  EXPECT_EQ(KdTreeAggregate::depthLimit(10, 1000), KdTreeAggregate::kMaxDepth);
}

// --- Every reference aggregate -------------------------------------------------------------

class ReferenceAggregate : public ::testing::TestWithParam<std::string> {};

TEST_P(ReferenceAggregate, EmptySceneMissesEverything) {
  SceneGeometry g;
  auto agg = make(GetParam(), g);
  EXPECT_TRUE(agg->worldBound().empty());
  SurfaceInteraction si;
  EXPECT_FALSE(agg->intersect(Ray(Point3f(0, 0, 0), Vector3f(0, 0, 1)), &si));
  EXPECT_FALSE(agg->intersectP(Ray(Point3f(0, 0, 0), Vector3f(0, 0, 1))));
}

TEST_P(ReferenceAggregate, HitsMissesAndTMax) {
  Scene s;
  s.geometry.primitives.reserve(3);  // no reallocation: an address is compared below
  const Primitive* near = &s.addSphere(translate(Vector3f(0, 0, 5)), 1, &s.geometry.primitives);
  s.addSphere(translate(Vector3f(0, 0, 10)), 1, &s.geometry.primitives);
  s.addSphere(translate(Vector3f(7, 0, 0)), 1, &s.geometry.primitives);
  auto agg = make(GetParam(), s.geometry);

  Ray r(Point3f(0, 0, 0), Vector3f(0, 0, 2));  // not unit: t is in units of |d|
  SurfaceInteraction si;
  ASSERT_TRUE(agg->intersect(r, &si));
  EXPECT_NEAR(r.tMax, 2, 1e-5);
  EXPECT_EQ(si.primitive, near);
  EXPECT_NEAR(si.p.z, 4, 1e-5);

  Ray shortRay(Point3f(0, 0, 0), Vector3f(0, 0, 1), 3.5f);
  EXPECT_FALSE(agg->intersect(shortRay, &si));
  EXPECT_EQ(shortRay.tMax, 3.5f);  // untouched by a miss
  EXPECT_FALSE(agg->intersectP(shortRay));
  EXPECT_TRUE(agg->intersectP(Ray(Point3f(0, 0, 0), Vector3f(0, 0, 1), 4.5f)));

  // From inside the first sphere: its far side, not the second sphere.
  Ray inside(Point3f(0, 0, 5), Vector3f(0, 0, 1));
  ASSERT_TRUE(agg->intersect(inside, &si));
  EXPECT_NEAR(inside.tMax, 1, 1e-5);
  // Pointing away from everything.
  EXPECT_FALSE(agg->intersect(Ray(Point3f(0, 0, 0), Vector3f(0, 0, -1)), &si));
  EXPECT_FALSE(agg->intersect(Ray(Point3f(0, 0, 0), Vector3f(0, 1, 0)), &si));
}

TEST_P(ReferenceAggregate, RefusesBadRays) {
  Scene s;
  s.addSphere(Transform(), 1, &s.geometry.primitives);
  auto agg = make(GetParam(), s.geometry);
  const Float nan = std::numeric_limits<Float>::quiet_NaN();
  std::vector<Ray> bad = {
      Ray(Point3f(nan, 0, -5), Vector3f(0, 0, 1)),
      Ray(Point3f(0, 0, -5), Vector3f(0, nan, 1)),
      Ray(Point3f(0, 0, -5), Vector3f(0, 0, 1), nan),
      Ray(Point3f(0, 0, -kInfinity), Vector3f(0, 0, 1)),
      Ray(Point3f(0, 0, -5), Vector3f(0, 0, kInfinity)),
      Ray(Point3f(0, 0, -5), Vector3f(0, 0, 0)),
      Ray(Point3f(0, 0, -5), Vector3f(-0.f, 0, -0.f)),
      Ray(Point3f(0, 0, -5), Vector3f(0, 0, 1), 0),
      Ray(Point3f(0, 0, -5), Vector3f(0, 0, 1), -1),
  };
  for (const Ray& r : bad) {
    SurfaceInteraction si;
    EXPECT_FALSE(agg->intersect(r, &si)) << r.o << " " << r.d << " " << r.tMax;
    EXPECT_FALSE(agg->intersectP(r)) << r.o << " " << r.d << " " << r.tMax;
  }
}

// Rays along voxel faces, split planes and mesh edges: a floor of unit squares with vertices at
// integers, rays straight down at integer and half-integer (x, y) and rays lying in the plane.
TEST_P(ReferenceAggregate, AxisParallelRaysOnCellFaces) {
  Scene s;
  s.addFloor(8, 0, &s.geometry.primitives);
  s.addSphere(translate(Vector3f(4, 4, 3)), 0.5f, &s.geometry.primitives);
  auto agg = make(GetParam(), s.geometry);
  for (int j = 0; j <= 16; ++j)
    for (int i = 0; i <= 16; ++i) {
      // -0 and +0 in x and y: the slab test sees 0 * inf = NaN at the bound's faces.
      Ray down(Point3f(i * 0.5f, j * 0.5f, 2), Vector3f(-0.f, 0.f, -1));
      SurfaceInteraction si;
      ASSERT_TRUE(agg->intersect(down, &si)) << i << " " << j;
      EXPECT_EQ(down.tMax, 2) << i << " " << j;
      EXPECT_TRUE(agg->intersectP(Ray(Point3f(i * 0.5f, j * 0.5f, 2), Vector3f(0, 0, -1))));
      EXPECT_FALSE(agg->intersectP(Ray(Point3f(i * 0.5f, j * 0.5f, 2), Vector3f(0, 0, -1), 1.9f)));
    }
  // From the floor's plane (z = 0, where the bound is flat) up to the sphere.
  Ray tilted(Point3f(-1, 4, 0), Vector3f(1, 0, 0.6f));
  SurfaceInteraction si;
  EXPECT_TRUE(agg->intersect(tilted, &si));
  // Outside the floor's x range, parallel to x: never enters the bound (tNear = tFar = +inf).
  EXPECT_FALSE(agg->intersectP(Ray(Point3f(-1, 20, 0), Vector3f(1, 0, 0))));
  EXPECT_FALSE(agg->intersectP(Ray(Point3f(20, 4, 3), Vector3f(0, 0, 1))));
}

TEST_P(ReferenceAggregate, InstancesStaticMirroredAndAnimated) {
  Scene s;
  InstancePrototype* proto = s.addPrototype("ball");
  proto->primitives.reserve(1);
  s.addSphere(Transform(), 1, &proto->primitives);
  const Primitive* ball = &proto->primitives[0];
  InstancePrototype* unused = s.addPrototype("unused");
  s.addSphere(Transform(), 1, &unused->primitives);
  s.geometry.instances.push_back(
      Instance{proto, AnimatedTransform(translate(Vector3f(5, 0, 0)) * scale(2, 2, 2))});
  s.geometry.instances.push_back(
      Instance{proto, AnimatedTransform(translate(Vector3f(-5, 0, 0)) * scale(-1, 1, 1))});
  s.geometry.instances.push_back(Instance{
      proto,
      AnimatedTransform(translate(Vector3f(0, 0, 10)), 0, translate(Vector3f(0, 8, 10)), 1)});
  auto agg = make(GetParam(), s.geometry);
  AggregateStats st = agg->stats();
  EXPECT_EQ(st.counts["instances"], 3);
  EXPECT_EQ(st.counts["prototypes"], 1);  // built once, and only if used
  EXPECT_LE(agg->worldBound().pMin.x, -6);
  EXPECT_GE(agg->worldBound().pMax.x, 7);
  EXPECT_GE(agg->worldBound().pMax.y, 9);  // the animated one's whole path

  // The scaled instance: radius 2 around (5, 0, 0), hit from +x at x = 7, normal +x.
  Ray r(Point3f(20, 0, 0), Vector3f(-1, 0, 0));
  SurfaceInteraction si;
  ASSERT_TRUE(agg->intersect(r, &si));
  EXPECT_NEAR(r.tMax, 13, 1e-4);
  EXPECT_EQ(si.primitive, ball);
  EXPECT_NEAR(si.p.x, 7, 1e-4);
  EXPECT_NEAR(si.n.x, 1, 1e-5);
  EXPECT_NEAR(si.wo.x, 1, 1e-6);
  EXPECT_GT(si.pError.x, 0);
  // The mirrored one: its normal still points out of the sphere.
  Ray m(Point3f(-20, 0, 0), Vector3f(1, 0, 0));
  ASSERT_TRUE(agg->intersect(m, &si));
  EXPECT_NEAR(m.tMax, 14, 1e-4);
  EXPECT_NEAR(si.n.x, -1, 1e-5);
  // The animated one, where it is at the ray's time.
  for (Float time : {0.f, 0.25f, 1.f}) {
    Float y = 8 * time;
    Ray a(Point3f(0, y, 0), Vector3f(0, 0, 1), kInfinity, time);
    ASSERT_TRUE(agg->intersect(a, &si)) << time;
    EXPECT_NEAR(a.tMax, 9, 1e-4) << time;
    EXPECT_NEAR(si.p.y, y, 1e-4) << time;
    Ray off(Point3f(0, y + 3, 0), Vector3f(0, 0, 1), kInfinity, time);
    EXPECT_FALSE(agg->intersectP(off)) << time;
  }
}

TEST_P(ReferenceAggregate, ConcurrentQueriesGiveTheSameAnswers) {
  // Mailboxes are per query: two threads tracing at once see what one thread sees.
  Scene s;
  RNG rng(9);
  for (int i = 0; i < 300; ++i) {
    Vector3f c(rng.uniformFloat() * 10, rng.uniformFloat() * 10, rng.uniformFloat() * 10);
    s.addSphere(translate(c), 0.3f + rng.uniformFloat(), &s.geometry.primitives);
  }
  auto agg = make(GetParam(), s.geometry);
  std::vector<Ray> rays;
  for (int i = 0; i < 4000; ++i) {
    Point3f o(rng.uniformFloat() * 10, rng.uniformFloat() * 10, -5);
    Vector3f d(rng.uniformFloat() - 0.5f, rng.uniformFloat() - 0.5f, 1);
    rays.emplace_back(o, d);
  }
  auto trace = [&](std::vector<Float>* out) {
    for (const Ray& r0 : rays) {
      Ray r = r0;
      SurfaceInteraction si;
      out->push_back(agg->intersect(r, &si) ? r.tMax : -1);
    }
  };
  std::vector<Float> serial, a, b;
  trace(&serial);
  std::thread ta(trace, &a), tb(trace, &b);
  ta.join();
  tb.join();
  EXPECT_EQ(a, serial);
  EXPECT_EQ(b, serial);
  long hits = std::count_if(serial.begin(), serial.end(), [](Float t) { return t > 0; });
  EXPECT_GT(hits, 1000);
}

INSTANTIATE_TEST_SUITE_P(Kinds, ReferenceAggregate, ::testing::Values("bvh", "kdtree", "grid"));

}  // namespace
}  // namespace candela
