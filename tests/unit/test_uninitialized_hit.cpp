// The path integrator keeps its hit record unzeroed (SurfaceInteraction(kUninitialized)): that is
// only sound while every aggregate writes every member of the record on a hit. Here a record
// filled with garbage bytes must come out of each aggregate bit for bit the same as a zeroed one,
// for every kind of hit: flat and smooth triangles, a quadric, a curve, an instance.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <utility>

#include "accel/aggregate_factory.h"
#include "shapes/curve_shape.h"
#include "shapes/sphere.h"
#include "shapes/triangle_mesh.h"
#include "support/param_items.h"
#include "support/test_device.h"

namespace candela {
namespace {

using test::floats;
using test::paramSet;
using test::points;
using test::strings;

// One primitive of each kind, apart along x, each hit by a ray straight down -z at its x.
struct Geometry {
  std::vector<std::unique_ptr<TriangleMesh>> meshes;
  std::vector<std::unique_ptr<Shape>> shapes;
  SceneGeometry geometry;

  void add(std::vector<std::unique_ptr<Shape>> s, std::vector<Primitive>* out) {
    for (auto& shape : s) {
      out->push_back(Primitive{shape.get(), nullptr, nullptr});
      shapes.push_back(std::move(shape));
    }
  }
  // A unit square at x0 in the plane z = 0, with per-vertex normals, tangents and uv if smooth.
  void addSquare(Float x0, bool smooth) {
    std::vector<Point3f> p{{x0 - 1, -1, 0}, {x0 + 1, -1, 0}, {x0 + 1, 1, 0}, {x0 - 1, 1, 0}};
    std::vector<Normal3f> n;
    std::vector<Vector3f> s;
    std::vector<Point2f> uv;
    if (smooth) {
      n = {{0.1f, 0, 1}, {0, 0.1f, 1}, {-0.1f, 0, 1}, {0, -0.1f, 1}};
      s = {{1, 0, 0}, {1, 0.1f, 0}, {1, 0, 0.1f}, {1, 0, 0}};
      uv = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    }
    meshes.push_back(std::make_unique<TriangleMesh>(
        Transform(), false, std::vector<int>{0, 1, 2, 0, 2, 3}, p, n, s, uv));
    add(createTriangleShapes(meshes.back().get()), &geometry.primitives);
  }
};

// Each member compared byte for byte (bytes may be read whatever they hold); padding is not
// compared.
template <typename T>
bool sameBits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}
void expectSameBits(const SurfaceInteraction& a, const SurfaceInteraction& b) {
  const auto &s = a.shading, &t = b.shading;
  const std::pair<const char*, bool> members[] = {{"p", sameBits(a.p, b.p)},
                                                  {"pError", sameBits(a.pError, b.pError)},
                                                  {"n", sameBits(a.n, b.n)},
                                                  {"wo", sameBits(a.wo, b.wo)},
                                                  {"time", sameBits(a.time, b.time)},
                                                  {"uv", sameBits(a.uv, b.uv)},
                                                  {"dpdu", sameBits(a.dpdu, b.dpdu)},
                                                  {"dpdv", sameBits(a.dpdv, b.dpdv)},
                                                  {"dndu", sameBits(a.dndu, b.dndu)},
                                                  {"dndv", sameBits(a.dndv, b.dndv)},
                                                  {"shading.n", sameBits(s.n, t.n)},
                                                  {"shading.dpdu", sameBits(s.dpdu, t.dpdu)},
                                                  {"shading.dpdv", sameBits(s.dpdv, t.dpdv)},
                                                  {"shading.dndu", sameBits(s.dndu, t.dndu)},
                                                  {"shading.dndv", sameBits(s.dndv, t.dndv)},
                                                  {"primitive", sameBits(a.primitive, b.primitive)},
                                                  {"dpdx", sameBits(a.dpdx, b.dpdx)},
                                                  {"dpdy", sameBits(a.dpdy, b.dpdy)},
                                                  {"dudx", sameBits(a.dudx, b.dudx)},
                                                  {"dvdx", sameBits(a.dvdx, b.dvdx)},
                                                  {"dudy", sameBits(a.dudy, b.dudy)},
                                                  {"dvdy", sameBits(a.dvdy, b.dvdy)}};
  for (const auto& [name, same] : members) EXPECT_TRUE(same) << name;
}

TEST(UninitializedHit, DefaultConstructionStillZeroes) {
  EXPECT_EQ(Vector3f(), Vector3f(0, 0, 0));
  EXPECT_EQ(Point3f(), Point3f(0, 0, 0));
  EXPECT_EQ(Normal3f(), Normal3f(0, 0, 0));
  EXPECT_EQ(Point2f(), Point2f(0, 0));
  SurfaceInteraction zeroed;
  EXPECT_EQ(zeroed.p, Point3f(0, 0, 0));
  EXPECT_EQ(zeroed.shading.dpdu, Vector3f(0, 0, 0));
  EXPECT_EQ(zeroed.dpdx, Vector3f(0, 0, 0));
  EXPECT_EQ(zeroed.primitive, nullptr);
}

class UninitializedHit : public ::testing::TestWithParam<const char*> {};

TEST_P(UninitializedHit, EveryAggregateWritesTheWholeRecordOnEveryKindOfHit) {
  Geometry g;
  g.addSquare(0, false);
  g.addSquare(4, true);
  std::vector<std::unique_ptr<Shape>> sphere;
  sphere.push_back(
      std::make_unique<SphereShape>(translate(Vector3f(8, 0, 0)), false, 1, -1, 1, 360));
  g.add(std::move(sphere), &g.geometry.primitives);
  g.add(createCurveShapes(Transform(), false,
                          paramSet({points("P", {12, -1, 0, 12, -0.3f, 0, 12, 0.3f, 0, 12, 1, 0}),
                                    strings("type", {"cylinder"}), floats("width", {0.5f})}),
                          FileLoc{}),
        &g.geometry.primitives);
  g.geometry.prototypes.push_back(std::make_unique<InstancePrototype>());
  InstancePrototype* proto = g.geometry.prototypes.back().get();
  proto->name = "ball";
  std::vector<std::unique_ptr<Shape>> ball;
  ball.push_back(std::make_unique<SphereShape>(Transform(), false, 1, -1, 1, 360));
  g.add(std::move(ball), &proto->primitives);
  g.geometry.instances.push_back(
      Instance{proto, AnimatedTransform(translate(Vector3f(16, 0, 0)) * scale(1, 2, 1))});
  auto aggregate = createAggregate(GetParam(), ParamSet{}, g.geometry, test::embreeDevice(),
                                   FileLoc{"test.pbrt", 1, 1});

  for (Float x : {0.3f, 4.2f, 3.7f, 8.1f, 12.05f, 16.2f}) {
    SCOPED_TRACE(x);
    Ray zeroRay(Point3f(x, 0.1f, 5), Vector3f(0, 0, -1)), garbageRay = zeroRay;
    SurfaceInteraction zeroed;
    ASSERT_TRUE(aggregate->intersect(zeroRay, &zeroed));
    // Garbage in every byte, the members the tag leaves unset and the ones it zeroes alike.
    SurfaceInteraction garbage(kUninitialized);
    std::memset(static_cast<void*>(&garbage), 0xa5, sizeof garbage);
    ASSERT_TRUE(aggregate->intersect(garbageRay, &garbage));
    EXPECT_EQ(zeroRay.tMax, garbageRay.tMax);
    expectSameBits(garbage, zeroed);
  }
}

INSTANTIATE_TEST_SUITE_P(Kinds, UninitializedHit,
                         ::testing::Values("embree", "bvh", "kdtree", "grid"));

}  // namespace
}  // namespace candela
