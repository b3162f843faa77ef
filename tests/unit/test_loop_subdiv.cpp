// Loop subdivision in our own code (seed 000 §3 "subdiv", §25 closed forms).
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "shapes/loop_subdiv.h"
#include "support/scene_error_of.h"

namespace candela {
namespace {

LoopMesh tetrahedron() {
  return {{{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}}, {0, 1, 2, 0, 2, 3, 0, 3, 1, 1, 3, 2}};
}

// A 4 x 4 vertex grid in the plane z = 2x + y, wound counter-clockwise from +z.
LoopMesh tiltedGrid() {
  LoopMesh m;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) m.p.emplace_back(Float(i), Float(j), Float(2 * i + j));
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      int a = 4 * j + i;
      for (int k : {a, a + 1, a + 5, a, a + 5, a + 4}) m.indices.push_back(k);
    }
  return m;
}

Vector3f faceNormal(const LoopMesh& m, int f) {
  const int* v = &m.indices[3 * f];
  return cross(m.p[v[1]] - m.p[v[0]], m.p[v[2]] - m.p[v[0]]);
}

TEST(LoopSubdiv, BetaClosedForms) {
  for (auto b : {LoopRules::Warren, LoopRules::Loop}) {
    EXPECT_DOUBLE_EQ(loopBeta(6, b), 1.0 / 16.0);
    EXPECT_DOUBLE_EQ(loopBeta(3, b), 3.0 / 16.0);
    EXPECT_DOUBLE_EQ(loopLimitGamma(6, b), 1.0 / 12.0);  // regular limit mask: 1/2, 1/12 each
  }
  EXPECT_DOUBLE_EQ(loopBeta(4, LoopRules::Warren), 3.0 / 32.0);
  EXPECT_DOUBLE_EQ(loopBeta(4, LoopRules::Loop), 31.0 / 256.0);
}

TEST(LoopSubdiv, MasksSumToOne) {
  // A translation of the control mesh translates every refined and limit vertex by the same
  // amount exactly when each mask's weights sum to 1.
  for (LoopMesh m : {tetrahedron(), tiltedGrid()})
    for (auto b : {LoopRules::Warren, LoopRules::Loop})
      for (auto bl : {LoopRules::Book, LoopRules::BSpline}) {
        LoopRules rules{b, bl};
        LoopMesh moved = m;
        Vector3f d(10, -20, 30);
        for (LoopPoint& p : moved.p) p = LoopPoint(p.x + d.x, p.y + d.y, p.z + d.z);
        LoopMesh r0 = refineLoop(m, 2, rules), r1 = refineLoop(moved, 2, rules);
        LoopLimit l0 = loopLimit(r0, buildLoopTopology(r0, {}, "t"), rules);
        LoopLimit l1 = loopLimit(r1, buildLoopTopology(r1, {}, "t"), rules);
        for (size_t i = 0; i < r0.p.size(); ++i) {
          EXPECT_LT(((r1.p[i] - r0.p[i]) - d).length(), 1e-4f);
          EXPECT_LT(((l1.p[i] - l0.p[i]) - d).length(), 1e-4f);
          EXPECT_LT((l1.n[i] - l0.n[i]).length(), 1e-4f);
        }
      }
  // And directly, valences 3 to 12.
  for (int n = 3; n <= 12; ++n)
    for (auto b : {LoopRules::Warren, LoopRules::Loop}) {
      double beta = loopBeta(n, b), gamma = loopLimitGamma(n, b);
      EXPECT_GT(1 - n * beta, 0);
      EXPECT_GT(1 - n * gamma, 0);
      EXPECT_GT(gamma, 0);
    }
}

TEST(LoopSubdiv, PlanarStaysPlanar) {
  LoopMesh m = tiltedGrid();
  LoopRules rules;
  LoopMesh r = refineLoop(m, 3, rules);
  LoopLimit l = loopLimit(r, buildLoopTopology(r, {}, "t"), rules);
  Vector3f expected = normalize(Vector3f(-2, -1, 1));
  for (size_t i = 0; i < r.p.size(); ++i) {
    EXPECT_NEAR(r.p[i].z, 2 * r.p[i].x + r.p[i].y, 1e-5f);
    EXPECT_NEAR(l.p[i].z, 2 * l.p[i].x + l.p[i].y, 1e-5f);
    EXPECT_NEAR(dot(Vector3f(l.n[i]), expected), 1, 1e-5f) << i;
  }
}

TEST(LoopSubdiv, LimitInsideControlHull) {
  // The tetrahedron's hull is itself: each limit point has non-negative barycentric coordinates
  // (signed distances to the four face planes all on the inner side).
  LoopMesh m = tetrahedron();
  for (auto b : {LoopRules::Warren, LoopRules::Loop}) {
    LoopRules rules{b, LoopRules::Book};
    LoopMesh r = refineLoop(m, 3, rules);
    LoopLimit l = loopLimit(r, buildLoopTopology(r, {}, "t"), rules);
    for (const LoopPoint& p : l.p)
      for (int f = 0; f < 4; ++f)
        EXPECT_LE(dot(faceNormal(m, f), p - m.p[m.indices[3 * f]]), 1e-5f);
  }
}

TEST(LoopSubdiv, ClosedTetrahedronStaysClosedAndOriented) {
  LoopMesh m = tetrahedron();
  LoopRules rules;
  LoopMesh r = refineLoop(m, 3, rules);
  ASSERT_EQ(r.faceCount(), 4 * 64);
  // Every directed edge once and its reverse once: closed, consistently oriented.
  std::set<std::pair<int, int>> directed;
  for (int f = 0; f < r.faceCount(); ++f)
    for (int i = 0; i < 3; ++i)
      EXPECT_TRUE(directed.insert({r.indices[3 * f + i], r.indices[3 * f + (i + 1) % 3]}).second);
  for (auto [a, b] : directed) EXPECT_TRUE(directed.count({b, a})) << a << " " << b;
  EXPECT_EQ(r.p.size() + r.faceCount() - directed.size() / 2, 2u);  // Euler characteristic
  // Faces wind outwards (the centroid is the origin), and so do the limit normals.
  LoopTopology t = buildLoopTopology(r, {}, "t");
  LoopLimit l = loopLimit(r, t, rules);
  for (int f = 0; f < r.faceCount(); ++f) {
    Vector3f c = (r.p[r.indices[3 * f]] - Point3f()) + (r.p[r.indices[3 * f + 1]] - Point3f());
    EXPECT_GT(dot(faceNormal(r, f), c), 0);
  }
  for (size_t v = 0; v < r.p.size(); ++v) {
    EXPECT_FALSE(t.boundary[v]);
    EXPECT_GT(dot(Vector3f(l.n[v]), l.p[v] - Point3f()), 0) << v;
  }
}

TEST(LoopSubdiv, OpenMeshNormalsFollowTheWinding) {
  // A bumped grid (boundary vertices of ring sizes 2, 3, 4): normals on the winding's side (+z).
  LoopMesh m = tiltedGrid();
  for (LoopPoint& p : m.p) p.z = (p.x == 1 && p.y == 1) ? 0.5 : 0.0;
  LoopRules rules;
  LoopMesh r = refineLoop(m, 2, rules);
  LoopLimit l = loopLimit(r, buildLoopTopology(r, {}, "t"), rules);
  for (size_t v = 0; v < r.p.size(); ++v) EXPECT_GT(l.n[v].z, 0.5f) << v;
}

TEST(LoopSubdiv, BoundaryLimitRules) {
  // The book's boundary limit differs from the B-spline's by (1/30)(first + last − 2v).
  LoopMesh m = tiltedGrid();
  for (LoopPoint& p : m.p) p.z = (int(p.x) * 7 + int(p.y) * 3) % 5;
  LoopTopology t = buildLoopTopology(m, {}, "t");
  LoopLimit book = loopLimit(m, t, {LoopRules::Warren, LoopRules::Book});
  LoopLimit spline = loopLimit(m, t, {LoopRules::Warren, LoopRules::BSpline});
  for (size_t v = 0; v < m.p.size(); ++v) {
    if (!t.boundary[v]) {
      EXPECT_EQ(book.p[v], spline.p[v]);
      continue;
    }
    std::span<const int> ring = t.ring(v);
    Vector3f d = ((m.p[ring.front()] - m.p[v]) + (m.p[ring.back()] - m.p[v])) / 30.f;
    EXPECT_LT(((book.p[v] - spline.p[v]) - d).length(), 1e-5f) << v;
  }
}

std::string errorOf(const LoopMesh& m) {
  return test::sceneErrorOf([&] {
    buildLoopTopology(m, FileLoc{"scene.lrt", 7, 3}, "loopsubdiv");
  });
}

TEST(LoopSubdiv, BadTopologyNamesTheFace) {
  LoopMesh m = tetrahedron();
  m.indices[7] = 9;
  EXPECT_EQ(errorOf(m),
            "scene.lrt:7:3: error: loopsubdiv: face 2 has vertex index 9, out of range [0, 4)");
  m = tetrahedron();
  m.indices[4] = 0;
  EXPECT_EQ(errorOf(m), "scene.lrt:7:3: error: loopsubdiv: face 1 repeats vertex 0");
  m = tetrahedron();
  m.p.emplace_back(0, 0, 5);
  for (int i : {0, 1, 4}) m.indices.push_back(i);  // a third face on edge (0, 1)
  EXPECT_NE(errorOf(m).find("face 4 has edge (0, 1) already shared by faces 0 and 2"),
            std::string::npos)
      << errorOf(m);
  m = tetrahedron();
  std::swap(m.indices[10], m.indices[11]);  // face 3 wound the other way
  EXPECT_NE(errorOf(m).find("face 3 winds edge"), std::string::npos) << errorOf(m);
  EXPECT_NE(errorOf(m).find("inconsistent orientation"), std::string::npos);
  // Two triangles sharing only vertex 0.
  m = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}}, {0, 1, 2, 0, 3, 4}};
  EXPECT_NE(errorOf(m).find("non-manifold vertex"), std::string::npos) << errorOf(m);
  EXPECT_NE(errorOf(m).find("face 1 "), std::string::npos) << errorOf(m);
  m.indices.pop_back();
  EXPECT_NE(errorOf(m).find("3 per triangle, found 5"), std::string::npos);
  // Two faces back to back: every edge has two faces and is wound both ways, but the refined mesh
  // would not be a manifold (it used to fail only at level 1, naming a refined face).
  m = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2, 0, 2, 1}};
  EXPECT_EQ(errorOf(m),
            "scene.lrt:7:3: error: loopsubdiv: face 0 and face 1 are the only faces "
            "around vertex 0 and lie back to back (an inner vertex needs three faces)");
}

// A fan of 200,000 faces around vertex 0. Lookups scan the edges kept at the end with fewer faces;
// when vertex 0, the smallest index, kept them all, this took about 10 s (50 ms now; timed by hand,
// not asserted).
TEST(LoopSubdiv, HighValenceFan) {
  const int n = 200000;
  LoopMesh m;
  m.p.emplace_back(0, 0, 0);
  for (int k = 0; k <= n; ++k) m.p.emplace_back(std::cos(k * 1e-5), std::sin(k * 1e-5), 0);
  for (int k = 1; k <= n; ++k)
    for (int v : {0, k, k + 1}) m.indices.push_back(v);
  LoopTopology t = buildLoopTopology(m, {}, "fan");
  EXPECT_EQ(t.ring(0).size(), size_t(n + 1));
  EXPECT_TRUE(t.boundary[0]);
  EXPECT_EQ(t.edges.size(), size_t(2 * n + 1));
}

}  // namespace
}  // namespace candela
