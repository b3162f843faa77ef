#include "shapes/loop_subdiv.h"

#include <cmath>
#include <deque>
#include <numbers>

namespace candela {

namespace {

// A weighted sum of points: a point when the weights sum to 1, a vector (a tangent) when to 0.
struct Sum {
  double x = 0, y = 0, z = 0;
  void add(const LoopPoint& p, double w) { x += w * p.x, y += w * p.y, z += w * p.z; }
  LoopPoint point() const { return LoopPoint(x, y, z); }
};

Sum cross(const Sum& a, const Sum& b) {
  return Sum{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// The weights of each valence, made on first use: per vertex, the trigonometry would cost more
// than the rest of the limit stage.
class ValenceWeights {
 public:
  explicit ValenceWeights(LoopRules::Beta beta) : beta_(beta) {}
  struct Weights {
    double beta = 0, gamma = 0;
    // Inside: cos and sin of 2πk/n. On a boundary of n ring vertices (n >= 5): the transverse
    // tangent's weights of ring vertex k (draft §3.7).
    std::vector<double> cos, sin, transverse;
  };
  const Weights& operator()(int n) {
    if (n >= int(table_.size())) table_.resize(size_t(n) + 1);
    Weights& w = table_[size_t(n)];
    if (w.cos.empty()) {
      w.beta = loopBeta(n, beta_);
      w.gamma = loopLimitGamma(n, beta_);
      for (int k = 0; k < n; ++k) {
        double a = 2 * std::numbers::pi * k / n;
        w.cos.push_back(std::cos(a));
        w.sin.push_back(std::sin(a));
      }
      if (n >= 5) {
        double theta = std::numbers::pi / (n - 1);
        w.transverse.assign(size_t(n), -std::sin(theta));
        for (int k = 1; k <= n - 2; ++k)
          w.transverse[size_t(k)] = -(2 * std::cos(theta) - 2) * std::sin(k * theta);
      }
    }
    return w;
  }

 private:
  LoopRules::Beta beta_;
  std::deque<Weights> table_;  // growing it keeps references to the entries made before
};

}  // namespace

double loopBeta(int n, LoopRules::Beta beta) {
  if (beta == LoopRules::Warren) return n == 3 ? 3.0 / 16.0 : 3.0 / (8.0 * n);
  double c = 3.0 / 8.0 + std::cos(2 * std::numbers::pi / n) / 4.0;
  return (5.0 / 8.0 - c * c) / n;
}

double loopLimitGamma(int n, LoopRules::Beta beta) {
  return 1.0 / (n + 3.0 / (8.0 * loopBeta(n, beta)));
}

LoopMesh refineLoopOnce(const LoopMesh& mesh, const LoopTopology& t, const LoopRules& rules) {
  int nv = int(mesh.p.size());
  LoopMesh out;
  out.p.resize(nv + t.edges.size());
  ValenceWeights weights(rules.beta);
  // Even vertices (draft §3.7): inside (1 − nβ) v + β Σ ring; on a boundary (3/4) v + (1/8) (the
  // two boundary neighbours), which ignores the interior and so keeps boundaries shared.
  for (int v = 0; v < nv; ++v) {
    std::span<const int> ring = t.ring(v);
    Sum s;
    if (ring.empty()) {
      s.add(mesh.p[v], 1);
    } else if (t.boundary[v]) {
      s.add(mesh.p[v], 0.75);
      s.add(mesh.p[ring.front()], 0.125);
      s.add(mesh.p[ring.back()], 0.125);
    } else {
      int n = int(ring.size());
      double b = weights(n).beta;
      s.add(mesh.p[v], 1 - n * b);
      for (int r : ring) s.add(mesh.p[r], b);
    }
    out.p[v] = s.point();
  }
  // Odd vertices: inside (3/8) the ends + (1/8) the two opposite vertices; on a boundary the
  // midpoint.
  for (size_t e = 0; e < t.edges.size(); ++e) {
    const LoopTopology::Edge& edge = t.edges[e];
    Sum s;
    if (edge.f[1] == -1) {
      s.add(mesh.p[edge.v[0]], 0.5);
      s.add(mesh.p[edge.v[1]], 0.5);
    } else {
      s.add(mesh.p[edge.v[0]], 0.375);
      s.add(mesh.p[edge.v[1]], 0.375);
      s.add(mesh.p[t.opposite(mesh, edge.f[0], int(e))], 0.125);
      s.add(mesh.p[t.opposite(mesh, edge.f[1], int(e))], 0.125);
    }
    out.p[nv + e] = s.point();
  }
  // The 4-way split; each child keeps its parent's winding.
  out.indices.reserve(4 * mesh.indices.size());
  for (int f = 0; f < mesh.faceCount(); ++f) {
    const int* v = &mesh.indices[3 * f];
    int m0 = nv + t.faceEdges[3 * f], m1 = nv + t.faceEdges[3 * f + 1],
        m2 = nv + t.faceEdges[3 * f + 2];
    for (int i : {v[0], m0, m2, v[1], m1, m0, v[2], m2, m1, m0, m1, m2}) out.indices.push_back(i);
  }
  return out;
}

LoopMesh refineLoop(const LoopMesh& control, int levels, const LoopRules& rules, const FileLoc& loc,
                    const std::string& shapeName) {
  LoopTopology t = buildLoopTopology(control, loc, shapeName);
  LoopMesh mesh = control;
  for (int level = 0; level < levels; ++level) {
    mesh = refineLoopOnce(mesh, t, rules);
    if (level + 1 < levels) t = buildLoopTopology(mesh, loc, shapeName);
  }
  return mesh;
}

namespace {

// The transverse limit tangent at a boundary vertex whose ring has n vertices (valence n in the
// draft: faces + 1), ring[0] and ring[n − 1] on the boundary; it points into the surface (draft
// §3.7, after Hoppe et al. 1994).
Sum boundaryTransverse(const LoopMesh& mesh, int v, std::span<const int> ring,
                       ValenceWeights& weights) {
  int n = int(ring.size());
  auto P = [&](int k) { return mesh.p[ring[k]]; };
  Sum s;
  if (n == 2) {
    s.add(P(0), 1), s.add(P(1), 1), s.add(mesh.p[v], -2);
  } else if (n == 3) {
    s.add(P(1), 1), s.add(mesh.p[v], -1);
  } else if (n == 4) {
    s.add(P(0), -1), s.add(P(1), 2), s.add(P(2), 2), s.add(P(3), -1), s.add(mesh.p[v], -2);
  } else {
    const std::vector<double>& w = weights(n).transverse;
    for (int k = 0; k < n; ++k) s.add(P(k), w[size_t(k)]);
  }
  return s;
}

}  // namespace

LoopLimit loopLimit(const LoopMesh& mesh, const LoopTopology& t, const LoopRules& rules) {
  int nv = int(mesh.p.size());
  LoopLimit out;
  out.p.resize(nv);
  out.n.resize(nv);
  ValenceWeights weights(rules.beta);
  for (int v = 0; v < nv; ++v) {
    std::span<const int> ring = t.ring(v);
    int n = int(ring.size());
    if (ring.empty()) {
      out.p[v] = mesh.p[v];
      continue;
    }
    Sum p;
    Sum normal;
    if (t.boundary[v]) {
      double side = rules.boundaryLimit == LoopRules::Book ? 0.2 : 1.0 / 6.0;
      p.add(mesh.p[v], 1 - 2 * side);
      p.add(mesh.p[ring.front()], side);
      p.add(mesh.p[ring.back()], side);
      // Along the boundary, last − first, points clockwise seen from the winding's side, so the
      // normal is transverse × along.
      Sum along;
      along.add(mesh.p[ring.back()], 1);
      along.add(mesh.p[ring.front()], -1);
      normal = cross(boundaryTransverse(mesh, v, ring, weights), along);
    } else {
      const ValenceWeights::Weights& w = weights(n);
      p.add(mesh.p[v], 1 - n * w.gamma);
      // S and T weigh the counter-clockwise ring by cos and sin: S × T follows the winding.
      Sum s, tt;
      for (int k = 0; k < n; ++k) {
        p.add(mesh.p[ring[k]], w.gamma);
        s.add(mesh.p[ring[k]], w.cos[size_t(k)]);
        tt.add(mesh.p[ring[k]], w.sin[size_t(k)]);
      }
      normal = cross(s, tt);
    }
    out.p[v] = p.point();
    double len = std::sqrt(normal.x * normal.x + normal.y * normal.y + normal.z * normal.z);
    if (len > 0)
      out.n[v] = Normal3f(Float(normal.x / len), Float(normal.y / len), Float(normal.z / len));
  }
  return out;
}

}  // namespace candela
