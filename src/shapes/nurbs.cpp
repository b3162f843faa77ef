#include "shapes/nurbs.h"

#include <fmt/format.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <string>

#include "shapes/bspline_basis.h"

namespace candela {

namespace {

using Vec3 = std::array<double, 3>;

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double length(const Vec3& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

// The tensor product of the two directions' bases applied to the homogeneous control points,
// then projected (the quotient rule for the derivatives). The weight sum is positive: weights
// are, and the basis functions are nonnegative and sum to one.
NurbsSample combine(const NurbsSurface& s, const BasisAt& bu, const BasisAt& bv) {
  std::array<double, 4> a{}, au{}, av{}, auv{};
  for (int l = 0; l < s.vorder; ++l) {
    const std::array<double, 4>* row = &s.pw[size_t(bv.first + l) * s.nu + bu.first];
    for (int k = 0; k < s.uorder; ++k) {
      double n = bu.value[k] * bv.value[l], nu = bu.derivative[k] * bv.value[l],
             nv = bu.value[k] * bv.derivative[l], nuv = bu.derivative[k] * bv.derivative[l];
      for (int c = 0; c < 4; ++c) {
        a[c] += n * row[k][c];
        au[c] += nu * row[k][c];
        av[c] += nv * row[k][c];
        auv[c] += nuv * row[k][c];
      }
    }
  }
  // A = w S differentiated: A_u = w_u S + w S_u, A_uv = w_uv S + w_u S_v + w_v S_u + w S_uv.
  NurbsSample out;
  for (int c = 0; c < 3; ++c) {
    out.p[c] = a[c] / a[3];
    out.dpdu[c] = (au[c] - au[3] * out.p[c]) / a[3];
    out.dpdv[c] = (av[c] - av[3] * out.p[c]) / a[3];
  }
  for (int c = 0; c < 3; ++c)
    out.d2pdudv[c] =
        (auv[c] - auv[3] * out.p[c] - au[3] * out.dpdv[c] - av[3] * out.dpdu[c]) / a[3];
  return out;
}

// A step from t into [t0, t1], towards the middle, for the last-resort normal.
double inward(double t, double t0, double t1) {
  double step = 1e-4 * (t1 - t0);
  return t < 0.5 * (t0 + t1) ? t + step : t - step;
}

// Tangents spanning a plane: their cross product is not lost to rounding.
bool transverse(const Vec3& n, const Vec3& a, const Vec3& b) {
  double len = length(n);
  return len > 0 && len > 1e-10 * length(a) * length(b);
}

struct Grid {
  const NurbsSurface& surface;
  double u0, u1, v0, v1;
  // How far the control net reaches along u (the largest distance of a point from the first of
  // its row) and along v (of its column): what a collapsed row or column is small against.
  double extentU, extentV;
};

// Whether dp/du vanishes structurally at the parameters of these bases: a single row of control
// points is in play (a clamped end, a C0 knot), and its points under the u support coincide (a
// pole). With u and v swapped (byColumn), dp/dv and a column.
//
// Decided on the control points, not on dp/du at the vertex: a pole makes dp/du vanish along the
// whole line, while a small dp/du at one vertex may be a cusp, where the pole's limit is wrong.
// The points are one when they are within 1e-5 of the net's extent in that direction (not of the
// coordinates: a narrow row far from the origin is no pole), or within 4 float ulps of their
// coordinates (a pole computed in float and written out lands within ~1 ulp per coordinate).
bool collapsed(const Grid& g, const BasisAt& along, const BasisAt& across, bool byColumn) {
  const NurbsSurface& s = g.surface;
  int line = -1;
  for (size_t r = 0; r < across.value.size(); ++r)
    if (across.value[r] >= 1 - 1e-12) line = across.first + int(r);
  if (line < 0) return false;
  auto point = [&](int k) {
    const std::array<double, 4>& q = byColumn ? s.pw[size_t(along.first + k) * s.nu + line]
                                              : s.pw[size_t(line) * s.nu + along.first + k];
    return Vec3{q[0] / q[3], q[1] / q[3], q[2] / q[3]};
  };
  Vec3 first = point(0);
  double spread = 0, magnitude = 0;
  for (int k = 0; k < int(along.value.size()); ++k) {
    Vec3 q = point(k);
    spread = std::max(spread, length({q[0] - first[0], q[1] - first[1], q[2] - first[2]}));
    magnitude = std::max({magnitude, std::abs(q[0]), std::abs(q[1]), std::abs(q[2])});
  }
  return spread <= std::max(1e-5 * (byColumn ? g.extentV : g.extentU), 4 * FLT_EPSILON * magnitude);
}

// Whether t is nearer the end than the start of the span the basis at t comes from: at a knot,
// whether the basis is the limit from below.
bool fromBelow(const std::vector<double>& knots, int order, const BasisAt& b, double t) {
  return knots[b.first + order] - t < t - knots[b.first + order - 1];
}

// dp/du x dp/dv at (u, v), unnormalized; zero when none is found. At a pole, where dp/du = 0 for
// all u, the normal's limit from inside is that of the first-order change of dp/du, the mixed
// derivative: dp/du (v + h) ~ h d2p/dudv, so N ~ ±d2p/dudv x dp/dv, the sign that of h on the
// side the basis was taken from (at an interior knot the right, at the patch's end the left);
// likewise for a collapsed column. Elsewhere degenerate (order 1, parallel tangents, both
// directions collapsed): the normal a small step inside the patch.
Vec3 surfaceNormal(const Grid& g, const BasisAt& bu, const BasisAt& bv, const NurbsSample& at,
                   double u, double v) {
  Vec3 a = at.dpdu, b = at.dpdv;
  auto towardsPatch = [](const Vec3& x, bool flip) { return flip ? Vec3{-x[0], -x[1], -x[2]} : x; };
  const NurbsSurface& s = g.surface;
  if (collapsed(g, bu, bv, false))
    a = towardsPatch(at.d2pdudv, fromBelow(s.vknots, s.vorder, bv, v));
  if (collapsed(g, bv, bu, true))
    b = towardsPatch(at.d2pdudv, fromBelow(s.uknots, s.uorder, bu, u));
  if (transverse(cross(a, b), a, b)) return cross(a, b);
  NurbsSample near = evaluateNurbs(g.surface, inward(u, g.u0, g.u1), inward(v, g.v0, g.v1));
  if (transverse(cross(near.dpdu, near.dpdv), near.dpdu, near.dpdv))
    return cross(near.dpdu, near.dpdv);
  return {0, 0, 0};
}

// n evenly spaced values from t0 to t1, both ends exact.
std::vector<double> samples(double t0, double t1, int n) {
  std::vector<double> t(n);
  for (int i = 0; i < n; ++i) {
    double f = double(i) / double(n - 1);
    t[i] = std::clamp((1 - f) * t0 + f * t1, t0, t1);
  }
  return t;
}

// m scaled to unit length, or zero if it has no direction (zero, or not finite). Scaled by its
// largest component first, so that huge or tiny finite vectors neither overflow nor underflow.
Vec3 unit(const Vec3& m) {
  if (!std::isfinite(m[0]) || !std::isfinite(m[1]) || !std::isfinite(m[2])) return {0, 0, 0};
  double big = std::max({std::abs(m[0]), std::abs(m[1]), std::abs(m[2])});
  if (!(big > 0)) return {0, 0, 0};
  Vec3 q{m[0] / big, m[1] / big, m[2] / big};
  double len = length(q);
  return {q[0] / len, q[1] / len, q[2] / len};
}

}  // namespace

NurbsSample evaluateNurbs(const NurbsSurface& s, double u, double v) {
  return combine(s, evaluateBasis(s.uknots, s.uorder, s.nu, u),
                 evaluateBasis(s.vknots, s.vorder, s.nv, v));
}

std::unique_ptr<TriangleMesh> makeNurbsMesh(const Transform& objectToWorld, bool reverseOrientation,
                                            const NurbsSurface& s, double u0, double u1, double v0,
                                            double v1, int diceu, int dicev) {
  std::vector<double> us = samples(u0, u1, diceu), vs = samples(v0, v1, dicev);
  // The bases along each grid line are shared by all the vertices on it. The last line takes the
  // limit from inside the patch: where u1 is an interior knot, the span to its left.
  std::vector<BasisAt> bu, bv;
  for (int i = 0; i < diceu; ++i)
    bu.push_back(evaluateBasis(s.uknots, s.uorder, s.nu, us[i], i + 1 == diceu));
  for (int j = 0; j < dicev; ++j)
    bv.push_back(evaluateBasis(s.vknots, s.vorder, s.nv, vs[j], j + 1 == dicev));

  auto control = [&s](int i, int j) {
    const std::array<double, 4>& q = s.pw[size_t(j) * s.nu + i];
    return Vec3{q[0] / q[3], q[1] / q[3], q[2] / q[3]};
  };
  auto distance = [](const Vec3& a, const Vec3& b) {
    return length({a[0] - b[0], a[1] - b[1], a[2] - b[2]});
  };
  Grid grid{s, u0, u1, v0, v1, 0, 0};
  for (int j = 0; j < s.nv; ++j)
    for (int i = 0; i < s.nu; ++i) {
      grid.extentU = std::max(grid.extentU, distance(control(i, j), control(0, j)));
      grid.extentV = std::max(grid.extentV, distance(control(i, j), control(i, 0)));
    }

  size_t count = size_t(diceu) * dicev;
  std::vector<Vec3> p(count), n(count);
  std::vector<Point2f> uv(count);
  for (int j = 0; j < dicev; ++j)
    for (int i = 0; i < diceu; ++i) {
      size_t k = size_t(j) * diceu + i;
      NurbsSample at = combine(s, bu[i], bv[j]);
      p[k] = at.p;
      n[k] = surfaceNormal(grid, bu[i], bv[j], at, us[i], vs[j]);
      uv[k] = Point2f(Float(us[i]), Float(vs[j]));
    }

  std::vector<int> indices;
  indices.reserve(size_t(diceu - 1) * (dicev - 1) * 6);
  auto vertex = [diceu](int i, int j) { return j * diceu + i; };
  for (int j = 0; j + 1 < dicev; ++j)
    for (int i = 0; i + 1 < diceu; ++i)
      for (int k : {vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j),
                    vertex(i + 1, j + 1), vertex(i, j + 1)})
        indices.push_back(k);

  // No normal from the surface (a degenerate patch): the area-weighted mean of the triangles
  // around the vertex, which share its winding; a vertex among degenerate triangles only gets +z.
  std::vector<Vec3> faceSum(count, Vec3{0, 0, 0});
  for (size_t t = 0; t < indices.size(); t += 3) {
    const Vec3 &a = p[indices[t]], &b = p[indices[t + 1]], &c = p[indices[t + 2]];
    Vec3 f =
        cross({b[0] - a[0], b[1] - a[1], b[2] - a[2]}, {c[0] - a[0], c[1] - a[1], c[2] - a[2]});
    for (int e = 0; e < 3; ++e)
      for (int c3 = 0; c3 < 3; ++c3) faceSum[indices[t + e]][c3] += f[c3];
  }
  std::vector<Point3f> points;
  std::vector<Normal3f> normals;
  points.reserve(count);
  normals.reserve(count);
  for (size_t k = 0; k < count; ++k) {
    Vec3 m = unit(n[k]);
    if (!(length(m) > 0)) m = unit(faceSum[k]);
    if (!(length(m) > 0)) m = {0, 0, 1};
    points.emplace_back(Float(p[k][0]), Float(p[k][1]), Float(p[k][2]));
    normals.emplace_back(Float(m[0]), Float(m[1]), Float(m[2]));
  }
  return std::make_unique<TriangleMesh>(objectToWorld, reverseOrientation, std::move(indices),
                                        std::move(points), std::move(normals),
                                        std::vector<Vector3f>(), std::move(uv));
}

namespace {

// The parameter names of one direction.
struct Names {
  const char *n, *order, *knots, *t0, *t1, *dice;
};
constexpr Names kU{"nu", "uorder", "uknots", "u0", "u1", "diceu"};
constexpr Names kV{"nv", "vorder", "vknots", "v0", "v1", "dicev"};

struct Direction {
  int n = 0, order = 0, dice = 0;
  std::vector<double> knots;
  double t0 = 0, t1 = 0;
};

class Reader {
 public:
  Reader(const ParamSet& params, const FileLoc& loc) : params_(params), loc_(loc) {}

  [[noreturn]] void fail(const char* name, const std::string& message) const {
    throw SceneError(params_.locationOf(name, loc_), fmt::format("nurbs: {}", message));
  }

  int requiredInt(const char* name) const {
    if (!params_.find(name)) fail(name, fmt::format("missing \"integer {}\"", name));
    return params_.getOneInt(name, 0);
  }

  Direction direction(const Names& nm) const {
    Direction d;
    d.n = requiredInt(nm.n);
    params_.requireInRange(nm.n, d.n, ValueRange::atLeast(1), loc_);
    d.order = requiredInt(nm.order);
    // The upper limit is the other parameter's value, so it is checked apart from the rule.
    params_.requireInRange(nm.order, d.order, ValueRange::atLeast(1), loc_);
    if (d.order > d.n)
      fail(nm.order, fmt::format("\"{}\" must be at most \"{}\" = {} (got {})", nm.order, nm.n, d.n,
                                 d.order));
    std::vector<Float> knots = params_.getFloatArray(nm.knots);
    if (knots.empty())
      fail(nm.knots, fmt::format("missing \"float {}\" ({} + {} knots)", nm.knots, nm.n, nm.order));
    // The sum in 64 bits: both are ints.
    long long want = (long long)d.n + d.order;
    if ((long long)knots.size() != want)
      fail(nm.knots, fmt::format("\"{}\" has {} values but {} + {} = {} + {} = {}", nm.knots,
                                 knots.size(), nm.n, nm.order, d.n, d.order, want));
    for (size_t i = 0; i < knots.size(); ++i) {
      if (!std::isfinite(knots[i]))
        fail(nm.knots, fmt::format("\"{}\"[{}] is not finite", nm.knots, i));
      if (i > 0 && knots[i] < knots[i - 1])
        fail(nm.knots, fmt::format("\"{}\" must be nondecreasing, but [{}] = {} follows [{}] = {}",
                                   nm.knots, i, knots[i], i - 1, knots[i - 1]));
    }
    d.knots.assign(knots.begin(), knots.end());
    double lo = d.knots[d.order - 1], hi = d.knots[d.n];
    if (!(lo < hi))
      fail(nm.knots, fmt::format("\"{}\" leave no parameter range: [{}] = [{}] = {}", nm.knots,
                                 d.order - 1, d.n, lo));
    d.t0 = params_.find(nm.t0) ? params_.getOneFloat(nm.t0, 0) : lo;
    d.t1 = params_.find(nm.t1) ? params_.getOneFloat(nm.t1, 0) : hi;
    for (auto [name, t] : {std::pair{nm.t0, d.t0}, std::pair{nm.t1, d.t1}}) {
      params_.requireInRange(name, t, ValueRange::finite(), loc_);
      if (!(t >= lo && t <= hi))
        fail(name, fmt::format("\"{}\" = {} is outside the knot range [{}, {}] ({}[{}] .. [{}])",
                               name, t, lo, hi, nm.knots, d.order - 1, d.n));
    }
    if (!(d.t0 < d.t1))
      fail(params_.find(nm.t1) ? nm.t1 : nm.t0,
           fmt::format("\"{}\" = {} must be less than \"{}\" = {}", nm.t0, d.t0, nm.t1, d.t1));
    d.dice = params_.getOneInt(nm.dice, 30, ValueRange::atLeast(2), loc_);
    return d;
  }

  // Control points as homogeneous (w x, w y, w z, w).
  std::vector<std::array<double, 4>> controlPoints(int nu, int nv) const {
    bool hasP = params_.find("P"), hasPw = params_.find("Pw");
    if (hasP && hasPw) fail("Pw", "give either \"point P\" or \"float Pw\", not both");
    if (!hasP && !hasPw) fail("P", "missing \"point P\" or \"float Pw\" (nu * nv control points)");
    long long count = (long long)nu * nv;
    std::vector<std::array<double, 4>> pw;
    if (hasP) {
      std::vector<Point3f> p = params_.getPoint3fArray("P");
      if ((long long)p.size() != count)
        fail("P", fmt::format("\"P\" has {} points but nu * nv = {} * {} = {}", p.size(), nu, nv,
                              count));
      for (size_t i = 0; i < p.size(); ++i) {
        if (!std::isfinite(p[i].x) || !std::isfinite(p[i].y) || !std::isfinite(p[i].z))
          fail("P", fmt::format("\"P\" point {} is not finite", i));
        pw.push_back({p[i].x, p[i].y, p[i].z, 1});
      }
      return pw;
    }
    std::vector<Float> f = params_.getFloatArray("Pw");
    if ((long long)f.size() != 4 * count)
      fail("Pw", fmt::format("\"Pw\" has {} values but 4 * nu * nv = 4 * {} * {} = {}", f.size(),
                             nu, nv, 4 * count));
    for (size_t i = 0; i < f.size(); i += 4) {
      for (size_t c = 0; c < 4; ++c)
        if (!std::isfinite(f[i + c]))
          fail("Pw", fmt::format("\"Pw\" point {} is not finite", i / 4));
      if (!(f[i + 3] > 0))
        fail("Pw", fmt::format("\"Pw\" point {} has weight {}: weights must be positive", i / 4,
                               f[i + 3]));
      // The surface lies in the hull of the projected points (the weights are positive): if they
      // fit in float, so do its points. A tiny weight can carry a point far beyond.
      double x = double(f[i]) / f[i + 3], y = double(f[i + 1]) / f[i + 3],
             z = double(f[i + 2]) / f[i + 3], most = std::numeric_limits<Float>::max();
      if (!(std::abs(x) <= most && std::abs(y) <= most && std::abs(z) <= most))
        fail("Pw", fmt::format("\"Pw\" point {} is at ({:g}, {:g}, {:g}), beyond float's range",
                               i / 4, x, y, z));
      pw.push_back({f[i], f[i + 1], f[i + 2], f[i + 3]});
    }
    return pw;
  }

 private:
  const ParamSet& params_;
  const FileLoc& loc_;
};

}  // namespace

std::vector<std::unique_ptr<Shape>> createNurbsShapes(const Transform& objectToWorld,
                                                      bool reverseOrientation,
                                                      const ParamSet& params,
                                                      std::unique_ptr<TriangleMesh>* meshOut,
                                                      const FileLoc& loc) {
  Reader read(params, loc);
  Direction u = read.direction(kU), v = read.direction(kV);
  // A bound well below int vertex indices: 2^24 vertices already take a few GB to build (two
  // triangle shapes each, double-precision scratch).
  long long vertices = (long long)u.dice * v.dice;
  if (vertices > (1LL << 24))
    read.fail(v.dice > u.dice ? "dicev" : "diceu",
              fmt::format("diceu * dicev = {} * {} = {} vertices is too many (at most {})", u.dice,
                          v.dice, vertices, 1LL << 24));
  NurbsSurface surface;
  surface.nu = u.n;
  surface.uorder = u.order;
  surface.uknots = std::move(u.knots);
  surface.nv = v.n;
  surface.vorder = v.order;
  surface.vknots = std::move(v.knots);
  surface.pw = read.controlPoints(u.n, v.n);
  std::unique_ptr<TriangleMesh> mesh = makeNurbsMesh(objectToWorld, reverseOrientation, surface,
                                                     u.t0, u.t1, v.t0, v.t1, u.dice, v.dice);
  // The points fit in float in object space (controlPoints); a transform can still carry them out
  // of range, and the mesh's bound and intersections would be NaN.
  for (size_t k = 0; k < mesh->p.size(); ++k) {
    const Point3f& q = mesh->p[k];
    const Normal3f& nn = mesh->n[k];
    bool pointOk = std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
    if (!pointOk || !std::isfinite(nn.x) || !std::isfinite(nn.y) || !std::isfinite(nn.z))
      read.fail(params.find("Pw") ? "Pw" : "P",
                fmt::format("the surface {} at (u, v) = ({}, {}) is not finite in float in world "
                            "space (the control points or the transform are too large)",
                            pointOk ? "normal" : "point", mesh->uv[k].x, mesh->uv[k].y));
  }
  std::vector<std::unique_ptr<Shape>> shapes = createTriangleShapes(mesh.get());
  *meshOut = std::move(mesh);
  return shapes;
}

}  // namespace candela
