// Our Loop subdivision against OpenSubdiv 3.5's (issue 4), at levels 1 to 4, on a tetrahedron, an
// icosahedron, open meshes with corners, valences 3 to 12 and a 3456-face grid (the killeroo
// itself is in test_loop_subdiv_killeroo.cpp, when the shared scenes are there): with OpenSubdiv's
// rules, LoopRules{Loop, BSpline}, every refined vertex, limit position and limit normal agrees;
// with the draft's, they differ by exactly the amounts loop_subdiv.h derives.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "shapes/opensubdiv_loop.h"

namespace candela {
namespace {

struct Case {
  std::string name;
  LoopMesh mesh;
};

void addFace(LoopMesh& m, int a, int b, int c) {
  for (int i : {a, b, c}) m.indices.push_back(i);
}

LoopMesh tetrahedron() {
  return {{{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}}, {0, 1, 2, 0, 2, 3, 0, 3, 1, 1, 3, 2}};
}

// The 20 triples of mutually adjacent vertices (edge length 2), each wound outwards.
LoopMesh icosahedron() {
  const Float g = (1 + std::sqrt(Float(5))) / 2;
  LoopMesh m;
  for (Float s : {-1.f, 1.f})
    for (Float t : {-1.f, 1.f}) {
      m.p.emplace_back(0, s, t * g);
      m.p.emplace_back(s, t * g, 0);
      m.p.emplace_back(t * g, 0, s);
    }
  auto adjacent = [&](int a, int b) { return std::abs(distance(m.p[a], m.p[b]) - 2) < 1e-3f; };
  for (int a = 0; a < 12; ++a)
    for (int b = a + 1; b < 12; ++b)
      for (int c = b + 1; c < 12; ++c)
        if (adjacent(a, b) && adjacent(b, c) && adjacent(a, c)) {
          Vector3f n = cross(m.p[b] - m.p[a], m.p[c] - m.p[a]);
          if (dot(n, m.p[a] - Point3f()) > 0)
            addFace(m, a, b, c);
          else
            addFace(m, a, c, b);
        }
  return m;
}

// A bumpy 5 x 4 grid: boundary vertices with one face (corners), two and three faces.
LoopMesh openGrid() {
  LoopMesh m;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 5; ++i)
      m.p.emplace_back(Float(i), Float(j), Float((i * 7 + j * 3) % 5) * 0.3f);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i) {
      int a = 5 * j + i;
      addFace(m, a, a + 1, a + 6);
      addFace(m, a, a + 6, a + 5);
    }
  return m;
}

// Interior valences 3 to 12 (the apexes of closed bipyramids; their rims have valence 4) and
// boundary vertices with 1 to 8 faces (the apexes of open fans), side by side in one mesh.
LoopMesh valences() {
  LoopMesh m;
  auto ring = [&](int n, Float x0, Float sweep) {
    int first = int(m.p.size());
    int count = sweep < 2 * kPi ? n + 1 : n;
    for (int k = 0; k < count; ++k) {
      Float a = sweep * k / n;
      m.p.emplace_back(x0 + std::cos(a), std::sin(a), 0.2f * Float(k % 3));
    }
    return first;
  };
  for (int n = 3; n <= 12; ++n) {
    Float x0 = Float(3 * n);
    int r = ring(n, x0, 2 * kPi);
    int top = int(m.p.size());
    m.p.emplace_back(x0, 0.1f, 1.f);
    m.p.emplace_back(x0, -0.1f, -1.f);
    for (int k = 0; k < n; ++k) {
      addFace(m, top, r + k, r + (k + 1) % n);
      addFace(m, top + 1, r + (k + 1) % n, r + k);
    }
  }
  for (int n = 1; n <= 8; ++n) {
    Float x0 = Float(3 * n);
    int r = ring(n, x0, kPi * 1.5f);
    for (int k = r; k < int(m.p.size()); ++k) m.p[k].y += 6;
    int apex = int(m.p.size());
    m.p.emplace_back(x0, 6.f, 0.5f);
    for (int k = 0; k < n; ++k) addFace(m, apex, r + k, r + k + 1);
  }
  return m;
}

// A killeroo-sized mesh that needs no shared scene: a bumpy open 48 x 36 grid whose quads are
// split along one diagonal or the other by a hash, which gives interior vertices of valences 4 to
// 8 and boundary vertices with 1 to 4 faces; 3456 faces.
LoopMesh flippedGrid() {
  const int nx = 48, ny = 36;
  LoopMesh m;
  auto hash = [](int i, int j) { return unsigned(i) * 73856093u ^ unsigned(j) * 19349663u; };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      m.p.emplace_back(0.5 * i, 0.5 * j, 0.05 * double(hash(i, j) % 17));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      int a = (nx + 1) * j + i, b = a + 1, c = a + nx + 2, d = a + nx + 1;
      if (hash(j, i) % 3 == 0) {
        addFace(m, a, b, c);
        addFace(m, a, c, d);
      } else {
        addFace(m, a, b, d);
        addFace(m, b, c, d);
      }
    }
  return m;
}

std::vector<Case> cases() {
  return {{"tetrahedron", tetrahedron()},
          {"icosahedron", icosahedron()},
          {"open grid", openGrid()},
          {"valences 3-12", valences()},
          {"flipped grid", flippedGrid()}};
}

Float diagonal(const LoopMesh& m) {
  Point3f lo = m.p[0].toPoint3f(), hi = lo;
  for (const LoopPoint& q : m.p) {
    Point3f p = q.toPoint3f();
    for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], p[i]), hi[i] = std::max(hi[i], p[i]);
  }
  return distance(lo, hi);
}

Float angle(const Normal3f& a, const Normal3f& b) {
  return std::atan2(cross(a, b).length(), dot(a, b));
}

TEST(LoopSubdivOpenSubdiv, MatchesWithOpenSubdivRules) {
  // Issue 4 asks for 1e-5 of the diagonal and 1e-3 rad. Both run in double, so the same rules
  // agree to rounding: 1e-12 of the diagonal, and 1e-6 rad (the normals are stored in float). That
  // the boundary vertices with 1 to 8 faces agree that closely rules out any difference in the
  // boundary tangent rules.
  const LoopRules rules{LoopRules::Loop, LoopRules::BSpline};
  for (const Case& c : cases()) {
    double tolerance = 1e-5 * diagonal(c.mesh);
    for (int levels = 1; levels <= 4; ++levels) {
      SCOPED_TRACE(c.name + ", level " + std::to_string(levels));
      LoopMesh ours = refineLoop(c.mesh, levels, rules);
      LoopLimit limit = loopLimit(ours, buildLoopTopology(ours, {}, "t"), rules);
      OsdLoopResult osd = refineLoopOpenSubdiv(c.mesh, levels, OsdBoundary::EdgeOnly);
      ASSERT_EQ(ours.p.size(), osd.refined.p.size());
      ASSERT_EQ(ours.faceCount(), osd.refined.faceCount());
      std::vector<int> fromOurs = openSubdivIndexOfOurs(c.mesh, levels);
      double worstP = 0, worstLimit = 0, worstAngle = 0;
      for (size_t v = 0; v < ours.p.size(); ++v) {
        int o = fromOurs[v];
        worstP = std::max(worstP, distance(ours.p[v], osd.refined.p[o]));
        worstLimit = std::max(worstLimit, distance(limit.p[v], osd.limitP[o]));
        worstAngle = std::max(worstAngle, double(angle(limit.n[v], osd.limitN[o])));
      }
      EXPECT_LE(worstP, tolerance);
      EXPECT_LE(worstLimit, tolerance);
      EXPECT_LT(worstAngle, 1e-3);
      EXPECT_LE(worstP, 1e-7 * tolerance);
      EXPECT_LE(worstLimit, 1e-7 * tolerance);
      EXPECT_LT(worstAngle, 1e-6);
    }
  }
}

TEST(LoopSubdivOpenSubdiv, DraftBetaDiffersByItsWeights) {
  // One level: an interior even vertex moves by (β_Warren − β_Loop)(Σ ring − n v) more with the
  // draft's β; odd vertices and boundary vertices do not change.
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    Float tolerance = 1e-5f * diagonal(c.mesh);
    LoopTopology t = buildLoopTopology(c.mesh, {}, "t");
    LoopMesh book = refineLoop(c.mesh, 1, {LoopRules::Warren, LoopRules::BSpline});
    OsdLoopResult osd = refineLoopOpenSubdiv(c.mesh, 1, OsdBoundary::EdgeOnly);
    std::vector<int> fromOurs = openSubdivIndexOfOurs(c.mesh, 1);
    bool anyDiffers = false;
    for (size_t v = 0; v < book.p.size(); ++v) {
      Vector3f expected;
      if (v < c.mesh.p.size() && !t.boundary[v]) {
        int n = int(t.ring(v).size());
        for (int r : t.ring(v)) expected += c.mesh.p[r] - c.mesh.p[v];
        expected *= Float(loopBeta(n, LoopRules::Warren) - loopBeta(n, LoopRules::Loop));
      }
      anyDiffers |= expected.length() > 100 * tolerance;
      EXPECT_LE(((book.p[v] - osd.refined.p[fromOurs[v]]) - expected).length(), tolerance) << v;
    }
    // Valences 3 and 6 have the same β under both (all the tetrahedron and grid have inside).
    EXPECT_EQ(anyDiffers,
              c.name == "icosahedron" || c.name == "valences 3-12" || c.name == "flipped grid");
  }
}

TEST(LoopSubdivOpenSubdiv, DraftBoundaryLimitDiffersByOneThirtieth) {
  LoopMesh control = openGrid();
  Float tolerance = 1e-5f * diagonal(control);
  for (int levels = 1; levels <= 3; ++levels) {
    LoopMesh ours = refineLoop(control, levels, {LoopRules::Loop, LoopRules::Book});
    LoopTopology t = buildLoopTopology(ours, {}, "t");
    LoopLimit book = loopLimit(ours, t, {LoopRules::Loop, LoopRules::Book});
    OsdLoopResult osd = refineLoopOpenSubdiv(control, levels, OsdBoundary::EdgeOnly);
    std::vector<int> fromOurs = openSubdivIndexOfOurs(control, levels);
    for (size_t v = 0; v < ours.p.size(); ++v) {
      Vector3f expected;
      if (t.boundary[v]) {
        std::span<const int> r = t.ring(int(v));
        expected = ((ours.p[r.front()] - ours.p[v]) + (ours.p[r.back()] - ours.p[v])) / 30.f;
      }
      EXPECT_LE(((book.p[v] - osd.limitP[fromOurs[v]]) - expected).length(), tolerance) << v;
    }
  }
}

TEST(LoopSubdivOpenSubdiv, EdgeAndCornerPinsCornersTheDraftDoesNot) {
  // Corners (one face) stay where they are with OpenSubdiv's EDGE_AND_CORNER; the draft (and
  // EDGE_ONLY) moves them. A closed mesh has no corners, and the option changes nothing.
  LoopMesh control = openGrid();
  LoopTopology t0 = buildLoopTopology(control, {}, "t");
  for (int levels = 1; levels <= 3; ++levels) {
    OsdLoopResult pinned = refineLoopOpenSubdiv(control, levels, OsdBoundary::EdgeAndCorner);
    std::vector<int> fromOurs = openSubdivIndexOfOurs(control, levels);
    LoopMesh ours = refineLoop(control, levels, {LoopRules::Loop, LoopRules::BSpline});
    int corners = 0;
    for (size_t v = 0; v < control.p.size(); ++v) {
      if (t0.ring(int(v)).size() != 2) continue;
      ++corners;
      EXPECT_EQ(pinned.refined.p[fromOurs[v]], control.p[v]);
      EXPECT_EQ(pinned.limitP[fromOurs[v]], control.p[v]);
      EXPECT_GT(distance(ours.p[v], control.p[v]), 1e-3f);
    }
    EXPECT_EQ(corners, 2);
  }
  LoopMesh ico = icosahedron();
  OsdLoopResult a = refineLoopOpenSubdiv(ico, 2, OsdBoundary::EdgeOnly);
  OsdLoopResult b = refineLoopOpenSubdiv(ico, 2, OsdBoundary::EdgeAndCorner);
  EXPECT_EQ(a.refined.p, b.refined.p);
}

TEST(LoopSubdivOpenSubdiv, BadTopologyNeverReachesOpenSubdiv) {
  LoopMesh m = tetrahedron();
  m.indices[5] = 1;
  EXPECT_THROW(refineLoopOpenSubdiv(m, 2, OsdBoundary::EdgeOnly), SceneError);
}

}  // namespace
}  // namespace candela
