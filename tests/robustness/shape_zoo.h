// One scene per kind of shape, under a given object-to-world transform, for the robustness tests:
// its shapes, meshes and primitives, and what the tests may assume about its geometry.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "shapes/cone.h"
#include "shapes/cylinder.h"
#include "shapes/disk.h"
#include "shapes/heightfield.h"
#include "shapes/hyperboloid.h"
#include "shapes/paraboloid.h"
#include "shapes/sphere.h"
#include "shapes/triangle_mesh.h"

namespace candela::test {

struct ShapeScene {
  std::string name;
  std::vector<std::unique_ptr<TriangleMesh>> meshes;
  std::vector<std::unique_ptr<Shape>> shapes;
  std::vector<Primitive> primitives;
  // Each primitive is planar (triangles): a ray leaving one can never hit it again.
  bool planarPrimitives = false;
  // A quadric: a line meets it at most twice, so a ray leaving it can meet it again only where
  // it crosses to the other side (dot(d, n) changes sign).
  bool quadric = false;
  // The surface bounds a convex region (or lies in a plane): a chord between two of its points
  // never meets it in between.
  bool convex = false;
  // Lies in a plane: a segment between two of its points lies in it too.
  bool planar = false;
  // No primitive can be hit from another one's surface (one flat mesh, or a single shape with
  // planarPrimitives).
  bool flat = false;

  void add(std::unique_ptr<Shape> s) {
    primitives.push_back(Primitive{s.get(), nullptr, nullptr});
    shapes.push_back(std::move(s));
  }
  void add(std::unique_ptr<TriangleMesh> m) {
    for (auto& s : createTriangleShapes(m.get())) add(std::move(s));
    meshes.push_back(std::move(m));
  }
};

// Every shape kind, each of size about 1 in object space. The quadrics are partial where that
// keeps them convex-bounded, so the clipping code runs too.
inline std::vector<std::unique_ptr<ShapeScene>> shapeZoo(const Transform& t) {
  std::vector<std::unique_ptr<ShapeScene>> zoo;
  auto scene = [&](const std::string& name) {
    zoo.push_back(std::make_unique<ShapeScene>());
    zoo.back()->name = name;
    return zoo.back().get();
  };
  ShapeScene* s = scene("sphere");
  s->add(std::make_unique<SphereShape>(t, false, 1, -1, 1, 360));
  s->quadric = s->convex = true;
  s = scene("cylinder");
  s->add(std::make_unique<CylinderShape>(t, false, 1, -1, 1, 300));
  s->quadric = s->convex = true;
  s = scene("disk");
  s->add(std::make_unique<DiskShape>(t, false, 0.1f, 1, 0.2f, 330));
  s->quadric = s->convex = s->planar = true;
  s = scene("cone");
  s->add(std::make_unique<ConeShape>(t, false, 1.5f, 1, 360));
  s->quadric = s->convex = true;
  s = scene("paraboloid");
  s->add(std::make_unique<ParaboloidShape>(t, false, 1, 0, 1.2f, 360));
  s->quadric = s->convex = true;
  s = scene("hyperboloid");
  s->add(std::make_unique<HyperboloidShape>(t, false, Point3f(1, 0.2f, -0.8f),
                                            Point3f(-0.3f, 0.9f, 0.9f), 330));
  s->quadric = true;
  s = scene("triangle");
  s->add(std::make_unique<TriangleMesh>(
      t, false, std::vector<int>{0, 1, 2},
      std::vector<Point3f>{{-1, -0.8f, 0.1f}, {1.1f, -0.5f, -0.2f}, {0.2f, 1, 0.3f}}));
  s->planarPrimitives = s->convex = s->flat = s->planar = true;
  // A wavy heightfield, centred on the origin: triangles may see each other, never themselves.
  s = scene("heightfield");
  {
    const int n = 24;
    std::vector<Float> z;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        z.push_back(0.15f * std::sin(9.f * i / n) * std::cos(7.f * j / n) + 0.02f * ((i * j) % 3));
    s->add(makeHeightfieldMesh(t * translate(Vector3f(-0.5f, -0.5f, 0)) * scale(2, 2, 1), false, n,
                               n, z));
  }
  s->planarPrimitives = true;
  // A flat heightfield: rays leaving it may hit nothing of it at all.
  s = scene("flat heightfield");
  s->add(makeHeightfieldMesh(t * translate(Vector3f(-0.5f, -0.5f, 0)) * scale(2, 2, 1), false, 9, 7,
                             std::vector<Float>(63, 0.25f)));
  s->planarPrimitives = s->convex = s->flat = s->planar = true;
  return zoo;
}

// The offsets and scales the robustness tests run at (each with a rotation, so that nothing is
// axis-aligned).
struct Placement {
  std::string name;
  Transform t;
};
inline std::vector<Placement> placements() {
  Transform r = rotate(33, Vector3f(1, -2, 0.7f));
  return {{"unit", r},
          {"at 1e5", translate(Vector3f(1e5f, 1e5f, 1e5f)) * r},
          {"scaled 1e-4", scale(1e-4f, 1e-4f, 1e-4f) * r},
          {"scaled 1e4", scale(1e4f, 1e4f, 1e4f) * r}};
}

}  // namespace candela::test
