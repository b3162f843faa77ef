// Instancing does not copy geometry: one 100k-triangle mesh instanced 10,000 times costs about
// one mesh plus a little per instance (DESIGN.md: static instances are Embree instances of one
// child scene per prototype). Flattening would cost 10,000 meshes, some hundreds of gigabytes.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>

#include "accel/embree/embree_aggregate.h"
#include "shapes/triangle_mesh.h"

namespace candela {
namespace {

// Resident set size of this process, from /proc/self/statm (second field, in pages).
long residentBytes() {
  std::ifstream statm("/proc/self/statm");
  long size = 0, resident = 0;
  statm >> size >> resident;
  return resident * sysconf(_SC_PAGESIZE);
}

// A flat n x n grid of squares over [0, 1]^2 at z = 0: 2 n^2 triangles.
std::unique_ptr<TriangleMesh> gridMesh(int n) {
  std::vector<Point3f> p;
  std::vector<int> idx;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) p.emplace_back(Float(i) / n, Float(j) / n, 0);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      int v00 = j * (n + 1) + i, v10 = v00 + 1, v01 = v00 + n + 1, v11 = v01 + 1;
      idx.insert(idx.end(), {v00, v10, v11, v00, v11, v01});
    }
  return std::make_unique<TriangleMesh>(Transform(), false, idx, p);
}

TEST(InstanceMemory, TenThousandInstancesCostAboutOneMesh) {
  static EmbreeDevice device;
  const int side = 224, instancesPerRow = 100, nInstances = instancesPerRow * instancesPerRow;
  long r0 = residentBytes();

  // The prototype: the mesh, its 100,352 triangle shapes and primitives.
  SceneGeometry geometry;
  std::unique_ptr<TriangleMesh> mesh = gridMesh(side);
  std::vector<std::unique_ptr<Shape>> shapes = createTriangleShapes(mesh.get());
  auto proto = std::make_unique<InstancePrototype>();
  for (const auto& s : shapes) proto->primitives.push_back(Primitive{s.get(), nullptr, nullptr});
  const InstancePrototype* prototype = proto.get();
  geometry.prototypes.push_back(std::move(proto));
  long r1 = residentBytes();

  // 10,000 instances on a 100 x 100 lattice, each turned a little.
  auto placement = [&](int k) {
    int i = k % instancesPerRow, j = k / instancesPerRow;
    return translate(Vector3f(2.f * i, 2.f * j, 0)) * rotateZ(Float(k % 37));
  };
  geometry.instances.reserve(nInstances);
  for (int k = 0; k < nInstances; ++k)
    geometry.instances.push_back(Instance{prototype, AnimatedTransform(placement(k))});
  EmbreeAggregate aggregate(device, geometry);
  long r2 = residentBytes();

  // Every instance is there: straight down onto the middle of each square.
  int hits = 0;
  for (int k = 0; k < nInstances; ++k) {
    Point3f centre = placement(k)(Point3f(0.5f, 0.5f, 0));
    Ray down(centre + Vector3f(0, 0, 3), Vector3f(0, 0, -1));
    SurfaceInteraction isect;
    if (aggregate.intersect(down, &isect) && std::abs(down.tMax - 3) < 1e-5f &&
        isect.primitive >= prototype->primitives.data() &&
        isect.primitive < prototype->primitives.data() + prototype->primitives.size())
      ++hits;
  }
  EXPECT_EQ(hits, nInstances);
  AggregateStats st = aggregate.stats();
  EXPECT_EQ(st.counts["embree instance geometries"], nInstances);
  EXPECT_EQ(st.counts["prototypes"], 1);
  EXPECT_EQ(st.counts["prototype triangles"], 2 * side * side);

  // The single mesh's own cost: its data (above) plus an Embree scene of it alone. Built after
  // the instances, it may reuse pages they freed, which can only make this figure smaller and
  // the bound below stricter.
  long r3 = residentBytes();
  long flatScene;
  {
    EmbreeAggregate single(device, prototype->primitives);
    flatScene = residentBytes() - r3;
  }
  long meshBytes = (r1 - r0) + flatScene;
  long instancedBytes = r2 - r0;
  long bound = 3 * meshBytes + 1024L * nInstances;
  std::printf(
      "[ info ] one mesh of %d triangles: %.1f MB (data %.1f MB, Embree scene %.1f MB); "
      "%d instances of it: %.1f MB in all, %.0f bytes per instance beyond the mesh; bound "
      "%.1f MB (3 meshes + 1 KB per instance); flattened would be about %.0f GB\n",
      2 * side * side, meshBytes / 1e6, (r1 - r0) / 1e6, flatScene / 1e6, nInstances,
      instancedBytes / 1e6, double(instancedBytes - meshBytes) / nInstances, bound / 1e6,
      double(meshBytes) * nInstances / 1e9);
  EXPECT_GT(meshBytes, 0);
  EXPECT_LT(instancedBytes, bound);
}

}  // namespace
}  // namespace candela
