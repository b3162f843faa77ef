// The "nurbs" shape: B-spline basis functions (partition of unity, nonnegativity, derivatives
// against finite differences and the Bernstein polynomials), surfaces with exactly known images
// (a plane, corner interpolation, the rational circle's cylinder and sphere), the mesh through
// the scene factory, and the factory's errors.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "assembly/shape_factory.h"
#include "core/rng.h"
#include "shapes/bspline_basis.h"
#include "shapes/nurbs.h"

namespace candela {
namespace {

// All count functions at t, zeros included, so bases found in different spans compare.
std::vector<double> dense(const BasisAt& b, int count, bool derivative) {
  std::vector<double> out(count, 0.0);
  const std::vector<double>& src = derivative ? b.derivative : b.value;
  for (size_t r = 0; r < src.size(); ++r) out[b.first + r] = src[r];
  return out;
}

struct KnotCase {
  const char* name;
  int order;
  std::vector<double> knots;
  int count() const { return int(knots.size()) - order; }
};

std::vector<KnotCase> knotCases() {
  return {{"order 1", 1, {0, 0.5, 0.5, 1, 2}},
          {"clamped linear", 2, {0, 0, 0.3, 1, 1}},
          {"uniform quadratic", 3, {0, 1, 2, 3, 4, 5, 6}},
          {"clamped cubic, double interior knot", 4, {0, 0, 0, 0, 0.2, 0.5, 0.5, 1, 1, 1, 1}},
          {"quintic, uneven", 6, {-1, -1, -1, -1, -1, -1, 0.1, 0.15, 2, 2, 2, 2, 2, 2}},
          {"nine-point circle", 3, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}}};
}

TEST(BsplineBasis, PartitionOfUnityAndNonnegative) {
  for (const KnotCase& c : knotCases()) {
    SCOPED_TRACE(c.name);
    double lo = c.knots[c.order - 1], hi = c.knots[c.count()];
    std::vector<double> ts;
    for (int k = 0; k <= 1000; ++k) ts.push_back(lo + (hi - lo) * k / 1000.0);
    for (double knot : c.knots)
      if (knot >= lo && knot <= hi) ts.push_back(knot);
    for (double t : ts) {
      BasisAt b = evaluateBasis(c.knots, c.order, c.count(), t);
      ASSERT_EQ(b.value.size(), size_t(c.order));
      ASSERT_GE(b.first, 0);
      ASSERT_LE(b.first + c.order, c.count());
      double sum = 0, dsum = 0;
      for (int r = 0; r < c.order; ++r) {
        EXPECT_GE(b.value[r], 0) << "t = " << t;
        sum += b.value[r];
        dsum += b.derivative[r];
      }
      EXPECT_NEAR(sum, 1, 1e-14) << "t = " << t;
      // The sum is constant, so its derivative is 0 (up to rounding of terms ~ order / span).
      EXPECT_NEAR(dsum, 0, 1e-10) << "t = " << t;
    }
  }
}

TEST(BsplineBasis, DerivativeMatchesFiniteDifferences) {
  RNG rng(7);
  for (const KnotCase& c : knotCases()) {
    SCOPED_TRACE(c.name);
    double lo = c.knots[c.order - 1], hi = c.knots[c.count()], h = 1e-6;
    for (int k = 0; k < 300; ++k) {
      double t = lo + 2 * h + (hi - lo - 4 * h) * rng.uniformFloat();
      // Central differences only within one span (the derivative jumps at knots of low order).
      if (findKnotSpan(c.knots, c.order, c.count(), t - h) !=
          findKnotSpan(c.knots, c.order, c.count(), t + h))
        continue;
      std::vector<double> d = dense(evaluateBasis(c.knots, c.order, c.count(), t), c.count(), true);
      std::vector<double> plus =
          dense(evaluateBasis(c.knots, c.order, c.count(), t + h), c.count(), false);
      std::vector<double> minus =
          dense(evaluateBasis(c.knots, c.order, c.count(), t - h), c.count(), false);
      for (int i = 0; i < c.count(); ++i) {
        // Error h^2 |N'''| / 6 + rounding 1e-16 / h: below 1e-7 for these knot spacings.
        EXPECT_NEAR(d[i], (plus[i] - minus[i]) / (2 * h), 1e-6 * (1 + std::abs(d[i])))
            << "t = " << t << " i = " << i;
      }
    }
  }
}

TEST(BsplineBasis, BezierKnotsGiveBernsteinPolynomials) {
  // Order 4 over (0, 0, 0, 0, 1, 1, 1, 1): N_i = C(3, i) t^i (1 - t)^(3 - i).
  std::vector<double> knots = {0, 0, 0, 0, 1, 1, 1, 1};
  for (int k = 0; k <= 50; ++k) {
    double t = k / 50.0, s = 1 - t;
    BasisAt b = evaluateBasis(knots, 4, 4, t);
    ASSERT_EQ(b.first, 0);
    double want[4] = {s * s * s, 3 * t * s * s, 3 * t * t * s, t * t * t};
    double dwant[4] = {-3 * s * s, 3 * s * s - 6 * t * s, 6 * t * s - 3 * t * t, 3 * t * t};
    for (int i = 0; i < 4; ++i) {
      EXPECT_NEAR(b.value[i], want[i], 1e-15);
      EXPECT_NEAR(b.derivative[i], dwant[i], 1e-14);
    }
  }
}

TEST(BsplineBasis, KnotSpans) {
  std::vector<double> knots = {0, 0, 0, 0.4, 0.4, 1, 1, 1};  // order 3, 5 functions
  EXPECT_EQ(findKnotSpan(knots, 3, 5, 0), 2);
  EXPECT_EQ(findKnotSpan(knots, 3, 5, 0.39), 2);
  EXPECT_EQ(findKnotSpan(knots, 3, 5, 0.4), 4);  // the span to the right of the double knot
  EXPECT_EQ(findKnotSpan(knots, 3, 5, 1), 4);    // the end: the last nonempty span
}

TEST(BsplineBasis, LeftLimitsAtKnots) {
  std::vector<double> knots = {0, 0, 0, 0.4, 0.4, 1, 1, 1};  // order 3, 5 functions
  EXPECT_EQ(findKnotSpan(knots, 3, 5, 0, true), 2);          // the start: the first span
  EXPECT_EQ(findKnotSpan(knots, 3, 5, 0.4, true), 2);  // the span to the left of the double knot
  EXPECT_EQ(findKnotSpan(knots, 3, 5, 0.7, true), 4);
  EXPECT_EQ(findKnotSpan(knots, 3, 5, 1, true), 4);
  // At every knot in the range, the basis from the left is the limit of the bases just below it
  // (the derivatives too, which jump at knots of multiplicity order - 1).
  const double h = 1e-9;
  for (const KnotCase& c : knotCases()) {
    SCOPED_TRACE(c.name);
    double lo = c.knots[c.order - 1], hi = c.knots[c.count()];
    for (double knot : c.knots) {
      if (!(knot > lo && knot <= hi)) continue;
      int s = findKnotSpan(c.knots, c.order, c.count(), knot, true);
      EXPECT_LT(c.knots[s], knot);
      EXPECT_GE(c.knots[s + 1], knot);
      BasisAt left = evaluateBasis(c.knots, c.order, c.count(), knot, true);
      BasisAt below = evaluateBasis(c.knots, c.order, c.count(), knot - h);
      std::vector<double> v = dense(left, c.count(), false), d = dense(left, c.count(), true);
      std::vector<double> vb = dense(below, c.count(), false), db = dense(below, c.count(), true);
      for (int i = 0; i < c.count(); ++i) {
        // h times the derivatives: |N'| < 1e3 and |N''| < 1e5 for these spans.
        EXPECT_NEAR(v[i], vb[i], 1e-6) << "knot " << knot << " i = " << i;
        EXPECT_NEAR(d[i], db[i], 1e-4) << "knot " << knot << " i = " << i;
      }
    }
  }
}

// A patch as plain data, then as the parameters of a scene statement. Each parameter has its own
// line, so that errors can be checked to be at the right one.
struct Patch {
  int nu = 0, uorder = 0, nv = 0, vorder = 0;
  std::vector<Float> uknots, vknots, P, Pw;
  std::vector<std::pair<std::string, Float>> floats;  // u0, u1, v0, v1
  std::vector<std::pair<std::string, int>> ints;      // diceu, dicev
};

int lineOf(const std::string& name) {
  const char* names[] = {"nu",     "uorder", "uknots", "u0", "u1", "nv",    "vorder",
                         "vknots", "v0",     "v1",     "P",  "Pw", "diceu", "dicev"};
  for (int i = 0; i < 14; ++i)
    if (name == names[i]) return i + 1;
  return 50;
}
constexpr int kShapeLine = 99;

ParamItem param(ParamType type, const std::string& typeName, const std::string& name) {
  ParamItem it;
  it.type = type;
  it.name = name;
  it.typeName = typeName;
  it.loc = FileLoc{"nurbs.pbrt", lineOf(name), 3};
  return it;
}

ParamSet toParams(const Patch& patch) {
  ParamSet ps;
  auto addInt = [&](const std::string& name, int v) {
    ParamItem it = param(ParamType::Integer, "integer", name);
    it.ints = {v};
    ps.add(it);
  };
  auto addFloats = [&](const std::string& name, const std::vector<Float>& v) {
    ParamItem it = param(ParamType::Float, "float", name);
    it.floats = v;
    ps.add(it);
  };
  addInt("nu", patch.nu);
  addInt("uorder", patch.uorder);
  addFloats("uknots", patch.uknots);
  addInt("nv", patch.nv);
  addInt("vorder", patch.vorder);
  addFloats("vknots", patch.vknots);
  if (!patch.P.empty()) {
    ParamItem it = param(ParamType::Point3, "point", "P");
    it.floats = patch.P;
    ps.add(it);
  }
  if (!patch.Pw.empty()) addFloats("Pw", patch.Pw);
  for (const auto& [name, v] : patch.floats) addFloats(name, {v});
  for (const auto& [name, v] : patch.ints) addInt(name, v);
  return ps;
}

NurbsSurface toSurface(const Patch& p) {
  NurbsSurface s;
  s.nu = p.nu;
  s.uorder = p.uorder;
  s.nv = p.nv;
  s.vorder = p.vorder;
  s.uknots.assign(p.uknots.begin(), p.uknots.end());
  s.vknots.assign(p.vknots.begin(), p.vknots.end());
  for (size_t i = 0; i < p.P.size(); i += 3) s.pw.push_back({p.P[i], p.P[i + 1], p.P[i + 2], 1});
  for (size_t i = 0; i < p.Pw.size(); i += 4)
    s.pw.push_back({p.Pw[i], p.Pw[i + 1], p.Pw[i + 2], p.Pw[i + 3]});
  return s;
}

// The plane map S(u, v) = o + u e1 + v e2. B-splines have linear precision: control points at the
// Greville abscissae (the means of order - 1 consecutive knots) reproduce it exactly.
const Vector3f kOrigin(0.5f, -1, 2), kE1(1, 0.25f, 0.5f), kE2(-0.5f, 2, 0.25f);

std::vector<Float> greville(const std::vector<Float>& knots, int order, int count) {
  std::vector<Float> g;
  for (int i = 0; i < count; ++i) {
    double sum = 0;
    for (int k = 1; k < order; ++k) sum += knots[i + k];
    g.push_back(Float(order > 1 ? sum / (order - 1) : knots[i]));
  }
  return g;
}

Patch planePatch(int uorder, std::vector<Float> uknots, int vorder, std::vector<Float> vknots) {
  Patch p;
  p.uorder = uorder;
  p.vorder = vorder;
  p.nu = int(uknots.size()) - uorder;
  p.nv = int(vknots.size()) - vorder;
  p.uknots = std::move(uknots);
  p.vknots = std::move(vknots);
  std::vector<Float> gu = greville(p.uknots, uorder, p.nu), gv = greville(p.vknots, vorder, p.nv);
  for (Float v : gv)
    for (Float u : gu) {
      Vector3f q = kOrigin + u * kE1 + v * kE2;
      p.P.insert(p.P.end(), {q.x, q.y, q.z});
    }
  return p;
}

TEST(Nurbs, LinearPrecisionReproducesThePlane) {
  struct Case {
    const char* name;
    Patch patch;
  };
  for (const Case& c : {Case{"bilinear", planePatch(2, {0, 0, 0.3f, 1, 1}, 2, {-1, -1, 2, 2})},
                        Case{"bicubic", planePatch(4, {0, 0, 0, 0, 0.5f, 1, 1, 1, 1}, 4,
                                                   {0, 0, 0, 0, 2, 2, 2, 2})}}) {
    SCOPED_TRACE(c.name);
    NurbsSurface s = toSurface(c.patch);
    double u0 = s.uknots[s.uorder - 1], u1 = s.uknots[s.nu];
    double v0 = s.vknots[s.vorder - 1], v1 = s.vknots[s.nv];
    // The evaluation in double, on control points placed in double: exact to rounding.
    NurbsSurface exact = s;
    for (int j = 0; j < s.nv; ++j)
      for (int i = 0; i < s.nu; ++i) {
        double gu = 0, gv = 0;
        for (int k = 1; k < s.uorder; ++k) gu += s.uknots[i + k] / (s.uorder - 1);
        for (int k = 1; k < s.vorder; ++k) gv += s.vknots[j + k] / (s.vorder - 1);
        for (int c3 = 0; c3 < 3; ++c3)
          exact.pw[size_t(j) * s.nu + i][c3] = kOrigin[c3] + gu * kE1[c3] + gv * kE2[c3];
      }
    RNG rng(3);
    for (int k = 0; k < 200; ++k) {
      double u = u0 + (u1 - u0) * rng.uniformFloat(), v = v0 + (v1 - v0) * rng.uniformFloat();
      NurbsSample at = evaluateNurbs(exact, u, v);
      for (int c3 = 0; c3 < 3; ++c3) {
        EXPECT_NEAR(at.p[c3], kOrigin[c3] + u * kE1[c3] + v * kE2[c3], 1e-13);
        EXPECT_NEAR(at.dpdu[c3], kE1[c3], 1e-13);
        EXPECT_NEAR(at.dpdv[c3], kE2[c3], 1e-13);
        EXPECT_NEAR(at.d2pdudv[c3], 0, 1e-13);
      }
    }
    auto mesh = makeNurbsMesh(Transform(), false, s, u0, u1, v0, v1, 7, 5);
    ASSERT_EQ(mesh->p.size(), 35u);
    ASSERT_EQ(mesh->n.size(), 35u);
    Normal3f want(normalize(cross(kE1, kE2)));
    for (size_t k = 0; k < mesh->p.size(); ++k) {
      Point3f q = Point3f(kOrigin) + mesh->uv[k].x * kE1 + mesh->uv[k].y * kE2;
      EXPECT_LT(distance(mesh->p[k], q), 1e-5f);
      EXPECT_GT(dot(mesh->n[k], want), 1 - 1e-6f);
    }
  }
}

TEST(Nurbs, RationalDerivativesMatchFiniteDifferences) {
  // Random points and weights in [0.2, 3] on uneven knots: dp/du, dp/dv from the quotient rule
  // and d2p/dudv against central differences of p and of dp/du.
  NurbsSurface s;
  s.nu = 5;
  s.uorder = 3;
  s.uknots = {0, 0, 0, 0.3, 0.45, 1, 1, 1};
  s.nv = 4;
  s.vorder = 4;
  s.vknots = {-1, -1, -1, -1, 2, 2, 2, 2};
  RNG rng(19);
  for (int k = 0; k < s.nu * s.nv; ++k) {
    double w = 0.2 + 2.8 * rng.uniformFloat();
    s.pw.push_back({w * (2 * rng.uniformFloat() - 1), w * (2 * rng.uniformFloat() - 1),
                    w * (2 * rng.uniformFloat() - 1), w});
  }
  const double h = 1e-6;
  double worst = 0;
  for (int k = 0; k < 200; ++k) {
    double u = 0.01 + 0.98 * rng.uniformFloat(), v = -0.97 + 2.94 * rng.uniformFloat();
    // Away from the knots 0.3 and 0.45, where the second derivative in u jumps.
    if (std::abs(u - 0.3) < 2 * h || std::abs(u - 0.45) < 2 * h) continue;
    NurbsSample at = evaluateNurbs(s, u, v);
    NurbsSample up = evaluateNurbs(s, u + h, v), um = evaluateNurbs(s, u - h, v);
    NurbsSample vp = evaluateNurbs(s, u, v + h), vm = evaluateNurbs(s, u, v - h);
    for (int c = 0; c < 3; ++c) {
      double du = (up.p[c] - um.p[c]) / (2 * h), dv = (vp.p[c] - vm.p[c]) / (2 * h);
      double duv = (vp.dpdu[c] - vm.dpdu[c]) / (2 * h);
      worst = std::max({worst, std::abs(du - at.dpdu[c]) / (1 + std::abs(at.dpdu[c])),
                        std::abs(dv - at.dpdv[c]) / (1 + std::abs(at.dpdv[c])),
                        std::abs(duv - at.d2pdudv[c]) / (1 + std::abs(at.d2pdudv[c]))});
    }
  }
  RecordProperty("maxRelativeDerivativeError", fmt::format("{:.3g}", worst));
  // h^2 times third derivatives (~1e2 here) plus rounding ~1e-16 / h: ~1e-9.
  EXPECT_LT(worst, 1e-6);
}

TEST(Nurbs, ClampedBicubicInterpolatesItsCorners) {
  Patch p;
  p.nu = 4;
  p.uorder = 4;
  p.uknots = {0, 0, 0, 0, 1, 1, 1, 1};
  p.nv = 5;
  p.vorder = 4;
  p.vknots = {0, 0, 0, 0, 0.4f, 1, 1, 1, 1};
  RNG rng(11);
  for (int i = 0; i < 3 * p.nu * p.nv; ++i) p.P.push_back(4 * rng.uniformFloat() - 2);
  NurbsSurface s = toSurface(p);
  auto control = [&](int i, int j) {
    const std::array<double, 4>& q = s.pw[size_t(j) * s.nu + i];
    return std::array<double, 3>{q[0], q[1], q[2]};
  };
  for (auto [i, j] : {std::pair{0, 0}, {3, 0}, {0, 4}, {3, 4}}) {
    NurbsSample at = evaluateNurbs(s, i == 0 ? 0 : 1, j == 0 ? 0 : 1);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(at.p[c], control(i, j)[c], 1e-14);
  }
  // The end tangent of a clamped curve: C'(0) = (k - 1) / (U[k] - U[1]) (P1 - P0), here 3 (P1 -
  // P0) along u and 3 / 0.4 (P1 - P0) along v.
  NurbsSample corner = evaluateNurbs(s, 0, 0);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(corner.dpdu[c], 3 * (control(1, 0)[c] - control(0, 0)[c]), 1e-12);
    EXPECT_NEAR(corner.dpdv[c], 3 / s.vknots[4] * (control(0, 1)[c] - control(0, 0)[c]), 1e-12);
  }
  auto mesh = makeNurbsMesh(Transform(), false, s, 0, 1, 0, 1, 6, 6);
  EXPECT_EQ(mesh->p[0], Point3f(p.P[0], p.P[1], p.P[2]));
  size_t last = size_t(3 * (p.nu * p.nv - 1));
  EXPECT_EQ(mesh->p.back(), Point3f(p.P[last], p.P[last + 1], p.P[last + 2]));
}

// The quadratic rational full circle of radius r in the plane z = 0 (The NURBS Book §7.5): nine
// points, the corners of the circumscribed square with weight √2/2 between the four points on
// the circle, knots (0, 0, 0, 1/4, 1/4, 1/2, 1/2, 3/4, 3/4, 1, 1, 1). {x, y, w}.
std::vector<std::array<double, 3>> circle(double r) {
  const double h = std::sqrt(0.5);
  return {{r, 0, 1},   {r, r, h},  {0, r, 1},  {-r, r, h}, {-r, 0, 1},
          {-r, -r, h}, {0, -r, 1}, {r, -r, h}, {r, 0, 1}};
}
const std::vector<Float> kCircleKnots = {0, 0, 0, 0.25f, 0.25f, 0.5f, 0.5f, 0.75f, 0.75f, 1, 1, 1};

struct Extremes {
  double position = 0, normal = 0;
};

TEST(Nurbs, RationalCylinderIsExact) {
  const double r = 2, z0 = -1, z1 = 1.5;
  Patch p;
  p.nu = 9;
  p.uorder = 3;
  p.uknots = kCircleKnots;
  p.nv = 2;
  p.vorder = 2;
  p.vknots = {0, 0, 1, 1};
  for (double z : {z0, z1})
    for (const auto& [x, y, w] : circle(r))
      p.Pw.insert(p.Pw.end(), {Float(w * x), Float(w * y), Float(w * z), Float(w)});
  p.ints = {{"diceu", 41}, {"dicev", 3}};
  std::unique_ptr<TriangleMesh> mesh;
  auto shapes = createNurbsShapes(Transform(), false, toParams(p), &mesh, FileLoc());
  ASSERT_EQ(mesh->p.size(), 123u);
  Extremes worst;
  for (size_t k = 0; k < mesh->p.size(); ++k) {
    Point3f q = mesh->p[k];
    double rho = std::hypot(double(q.x), double(q.y));
    worst.position = std::max(worst.position, std::abs(rho - r) / r);
    EXPECT_NEAR(q.z, z0 + (z1 - z0) * mesh->uv[k].y, 1e-6);
    // Outward (u counterclockwise about +z, v up), horizontal.
    Normal3f radial(Float(q.x / rho), Float(q.y / rho), 0);
    worst.normal = std::max(worst.normal, double(Vector3f(mesh->n[k] - radial).length()));
  }
  RecordProperty("maxRelativeRadiusError", fmt::format("{:.3g}", worst.position));
  RecordProperty("maxNormalError", fmt::format("{:.3g}", worst.normal));
  EXPECT_LT(worst.position, 1e-6);
  EXPECT_LT(worst.normal, 1e-5);
  // The nonrational curve on the same points would bulge to ~1.06 r at 45°: the weights matter.
  NurbsSample mid = evaluateNurbs(toSurface(p), 0.125, 0.5);
  EXPECT_NEAR(std::hypot(mid.p[0], mid.p[1]), r, 1e-6 * r);
}

// A sphere of radius r as a surface of revolution: the circle in u times a half circle from the
// south pole to the north pole in v, whose end rows of control points collapse to the poles.
TEST(Nurbs, SpherePolesGetRadialNormals) {
  const double r = 1.5, h = std::sqrt(0.5);
  const double profile[5][3] = {
      {0, -r, 1}, {r, -r, h}, {r, 0, 1}, {r, r, h}, {0, r, 1}};  // ρ, z, w
  Patch p;
  p.nu = 9;
  p.uorder = 3;
  p.uknots = kCircleKnots;
  p.nv = 5;
  p.vorder = 3;
  p.vknots = {0, 0, 0, 0.5f, 0.5f, 1, 1, 1};
  for (const auto& [rho, z, wv] : profile)
    for (const auto& [x, y, wu] : circle(1)) {
      double w = wu * wv;
      p.Pw.insert(p.Pw.end(), {Float(w * rho * x), Float(w * rho * y), Float(w * z), Float(w)});
    }
  p.ints = {{"diceu", 13}, {"dicev", 9}};
  std::unique_ptr<TriangleMesh> mesh;
  auto shapes = createNurbsShapes(Transform(), false, toParams(p), &mesh, FileLoc());
  ASSERT_EQ(mesh->n.size(), size_t(13 * 9));
  Extremes worst;
  for (size_t k = 0; k < mesh->p.size(); ++k) {
    Vector3f q(mesh->p[k]);
    worst.position = std::max(worst.position, std::abs(double(q.length()) - r) / r);
    ASSERT_TRUE(std::isfinite(mesh->n[k].x) && std::isfinite(mesh->n[k].y) &&
                std::isfinite(mesh->n[k].z));
    worst.normal = std::max(worst.normal, double((Vector3f(mesh->n[k]) - normalize(q)).length()));
  }
  RecordProperty("maxRelativeRadiusError", fmt::format("{:.3g}", worst.position));
  RecordProperty("maxNormalError", fmt::format("{:.3g}", worst.normal));
  EXPECT_LT(worst.position, 1e-6);
  EXPECT_LT(worst.normal, 1e-5);
  // The poles themselves: rows v = 0 and v = 1.
  for (int i = 0; i < 13; ++i) {
    EXPECT_NEAR(mesh->n[i].z, -1, 1e-6);
    EXPECT_NEAR(mesh->n[8 * 13 + i].z, 1, 1e-6);
  }
}

TEST(Nurbs, DegeneratePatchesGetFiniteNormals) {
  // Every control point the same (zero area), and order 1 in u (a staircase: dp/du = 0).
  Patch point = planePatch(2, {0, 0, 1, 1}, 2, {0, 0, 1, 1});
  for (Float& x : point.P) x = 0.25f;
  Patch steps = planePatch(1, {0, 1, 2, 3}, 2, {0, 0, 1, 1});
  for (const Patch* p : {&point, &steps}) {
    auto mesh = makeNurbsMesh(Transform(), false, toSurface(*p), p->uknots[p->uorder - 1],
                              p->uknots[p->nu], 0, 1, 5, 5);
    for (const Normal3f& n : mesh->n) {
      ASSERT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
      EXPECT_NEAR(n.length(), 1, 1e-6f);
    }
  }
}

TEST(Nurbs, SceneFactoryMeshAndHits) {
  // The bilinear plane over a sub-range, 5 x 4 vertices; then pbrt-v2's default: 30 x 30 over the
  // whole valid range of an unclamped knot vector.
  ShapeDesc desc;
  desc.name = "nurbs";
  Patch p = planePatch(2, {0, 0, 0.3f, 1, 1}, 2, {-1, -1, 2, 2});
  p.floats = {{"u0", 0.25f}, {"u1", 0.75f}, {"v0", 0}, {"v1", 1.5f}};
  p.ints = {{"diceu", 5}, {"dicev", 4}};
  desc.params = toParams(p);
  CreatedShapes out = createShapes(desc, Transform());
  ASSERT_EQ(out.shapes.size(), size_t((5 - 1) * (4 - 1) * 2));
  ASSERT_TRUE(out.mesh);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 5; ++i) {
      Point2f uv = out.mesh->uv[size_t(j) * 5 + i];
      EXPECT_NEAR(uv.x, 0.25f + 0.5f * i / 4, 1e-7f);
      EXPECT_NEAR(uv.y, 1.5f * j / 3, 1e-7f);
    }
  // Rays along -n at surface points: each hit's (u, v) is the point's (the map is affine, so the
  // mesh's barycentric (u, v) is exact).
  Vector3f n = normalize(cross(kE1, kE2));
  RNG rng(5);
  for (int k = 0; k < 200; ++k) {
    Float u = 0.26f + 0.48f * rng.uniformFloat(), v = 0.01f + 1.48f * rng.uniformFloat();
    Point3f target = Point3f(kOrigin) + u * kE1 + v * kE2;
    Ray ray(target + 3 * n, -n);
    int hits = 0;
    for (const auto& s : out.shapes) {
      Float t;
      SurfaceInteraction si;
      if (!s->intersect(ray, &t, &si)) continue;
      ++hits;
      EXPECT_NEAR(t, 3, 1e-5f);
      EXPECT_NEAR(si.uv.x, u, 1e-5f);
      EXPECT_NEAR(si.uv.y, v, 1e-5f);
      EXPECT_GT(dot(si.shading.n, n), 1 - 1e-5f);
    }
    EXPECT_GE(hits, 1);
  }

  Patch q = planePatch(3, {0, 1, 2, 3, 4, 5, 6}, 2, {0, 0, 1, 1});
  desc.params = toParams(q);
  CreatedShapes whole = createShapes(desc, Transform());
  EXPECT_EQ(whole.shapes.size(), size_t(29 * 29 * 2));
  EXPECT_EQ(whole.mesh->uv.front(), Point2f(2, 0));  // uknots[uorder - 1]
  EXPECT_EQ(whole.mesh->uv.back(), Point2f(4, 1));   // uknots[nu]
}

// Rule errors ("\"nv\" must be at least 1 (got 0)") are worded alike for every plug-in and do not
// name the shape; the nurbs' own errors do.
void expectError(const Patch& patch, int line, const std::string& words, bool namesShape = true) {
  std::unique_ptr<TriangleMesh> mesh;
  try {
    createNurbsShapes(Transform(), false, toParams(patch), &mesh,
                      FileLoc{"nurbs.pbrt", kShapeLine, 1});
    ADD_FAILURE() << "expected a SceneError about " << words;
  } catch (const SceneError& e) {
    EXPECT_EQ(e.location().line, line) << e.what();
    if (namesShape) {
      EXPECT_NE(std::string(e.what()).find("nurbs: "), std::string::npos) << e.what();
    }
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(Nurbs, FactoryErrors) {
  const Patch good = planePatch(2, {0, 0, 0.3f, 1, 1}, 3, {0, 0, 0, 1, 1, 1});
  auto with = [&](auto change) {
    Patch p = good;
    change(p);
    return p;
  };
  expectError(with([](Patch& p) { p.uknots.pop_back(); }), lineOf("uknots"),
              "\"uknots\" has 4 values but nu + uorder = 3 + 2 = 5");
  expectError(with([](Patch& p) { p.vknots[3] = -0.5f; }), lineOf("vknots"),
              "\"vknots\" must be nondecreasing, but [3] = -0.5 follows [2] = 0");
  expectError(with([](Patch& p) {
                p.uknots = {0, 0.5f, 0.5f, 0.5f, 1};
              }),
              lineOf("uknots"), "\"uknots\" leave no parameter range");
  expectError(with([](Patch& p) { p.uorder = 0; }), lineOf("uorder"),
              "\"uorder\" must be at least 1 (got 0)", false);
  expectError(with([](Patch& p) { p.vorder = 4; }), lineOf("vorder"),
              "\"vorder\" must be at most \"nv\" = 3 (got 4)");
  expectError(with([](Patch& p) { p.nv = 0; }), lineOf("nv"), "\"nv\" must be at least 1 (got 0)",
              false);
  expectError(with([](Patch& p) { p.P.resize(p.P.size() - 3); }), lineOf("P"),
              "\"P\" has 8 points but nu * nv = 3 * 3 = 9");
  expectError(with([](Patch& p) { p.Pw = std::vector<Float>(36, 1); }), lineOf("Pw"),
              "either \"point P\" or \"float Pw\", not both");
  expectError(with([](Patch& p) { p.P.clear(); }), kShapeLine,
              "missing \"point P\" or \"float Pw\"");
  auto weighted = [&](Float w4) {
    return with([w4](Patch& p) {
      p.Pw.clear();
      for (size_t i = 0; i < p.P.size(); i += 3)
        p.Pw.insert(p.Pw.end(), {p.P[i], p.P[i + 1], p.P[i + 2], i == 12 ? w4 : 1});
      p.P.clear();
    });
  };
  expectError(weighted(0), lineOf("Pw"), "\"Pw\" point 4 has weight 0: weights must be positive");
  expectError(weighted(-2), lineOf("Pw"), "\"Pw\" point 4 has weight -2");
  expectError(with([](Patch& p) {
                p.Pw = std::vector<Float>(35, 1);
                p.P.clear();
              }),
              lineOf("Pw"), "\"Pw\" has 35 values but 4 * nu * nv = 4 * 3 * 3 = 36");
  expectError(with([](Patch& p) {
                p.floats = {{"u0", 0.5f}, {"u1", 0.5f}};
              }),
              lineOf("u1"), "\"u0\" = 0.5 must be less than \"u1\" = 0.5");
  expectError(with([](Patch& p) {
                p.floats = {{"u0", -0.25f}};
              }),
              lineOf("u0"), "\"u0\" = -0.25 is outside the knot range [0, 1]");
  expectError(with([](Patch& p) {
                p.floats = {{"v1", 1.5f}};
              }),
              lineOf("v1"), "\"v1\" = 1.5 is outside the knot range [0, 1]");
  expectError(with([](Patch& p) {
                p.ints = {{"dicev", 1}};
              }),
              lineOf("dicev"), "\"dicev\" must be at least 2 (got 1)", false);
  expectError(with([](Patch& p) { p.P[7] = std::numeric_limits<Float>::infinity(); }), lineOf("P"),
              "\"P\" point 2 is not finite");
  ParamSet noNu = toParams(good);
  try {
    std::unique_ptr<TriangleMesh> mesh;
    ParamSet ps;
    for (const ParamItem& it : noNu.items())
      if (it.name != "nu") ps.add(it);
    createNurbsShapes(Transform(), false, ps, &mesh, FileLoc{"nurbs.pbrt", kShapeLine, 1});
    ADD_FAILURE();
  } catch (const SceneError& e) {
    EXPECT_EQ(e.location().line, kShapeLine);
    EXPECT_NE(std::string(e.what()).find("nurbs: missing \"integer nu\""), std::string::npos)
        << e.what();
  }
}

// The angle between two directions, accurate near 0 (acos loses half the digits there).
double angleBetween(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  std::array<double, 3> c = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                             a[0] * b[1] - a[1] * b[0]};
  return std::atan2(std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]),
                    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
}

std::array<double, 3> asArray(const Normal3f& n) { return {n.x, n.y, n.z}; }

// The exact surface normal at (u, v), from the derivatives in double.
std::array<double, 3> exactNormal(const NurbsSurface& s, double u, double v) {
  NurbsSample at = evaluateNurbs(s, u, v);
  const auto &a = at.dpdu, &b = at.dpdv;
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

TEST(Nurbs, NormalsDoNotDependOnWhereThePatchIs) {
  // A bicubic patch 0.06 wide in u and 1 long in v, with bumps in z, at the origin and moved by
  // 1e4 and 1e5 along x. No row or column of it is a pole, so every vertex normal is the exact
  // one; the boundary rows, 0.06 wide, once counted as poles far from the origin (tolerance 1e-5
  // of the largest coordinate), which turned their normals by 90 degrees. At 1e5 the rows are
  // still 5 float ulps of x wide: above the rounding a pole written in float can have.
  for (double offset : {0.0, 1e4, 1e5}) {
    SCOPED_TRACE(fmt::format("offset {}", offset));
    NurbsSurface s;
    s.nu = s.nv = s.uorder = s.vorder = 4;
    s.uknots = s.vknots = {0, 0, 0, 0, 1, 1, 1, 1};
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i)
        s.pw.push_back({offset + 0.02 * i, j / 3.0, 0.3 * (i * j % 3), 1});
    auto mesh = makeNurbsMesh(Transform(), false, s, 0, 1, 0, 1, 9, 9);
    double worst = 0;
    for (int j = 0; j < 9; ++j)
      for (int i = 0; i < 9; ++i)
        worst = std::max(worst, angleBetween(asArray(mesh->n[size_t(j) * 9 + i]),
                                             exactNormal(s, i / 8.0, j / 8.0)));
    RecordProperty(fmt::format("maxNormalAngleAtOffset{:g}", offset), fmt::format("{:.3g}", worst));
    // Float normals round at ~6e-8 per component; the derivatives at 1e5 lose ~1e-10 to
    // cancellation.
    EXPECT_LT(worst, 1e-6);
  }
}

// An hourglass: the quadratic rational circle in u swept along the profile (ρ, z) = (1, -1),
// (0, 0), (1, 1) of order 2 in v, with the pinch, a pole row, at the interior knot v = 1.25 of
// [0, 2]. Both halves are cones, so the normal is constant along each generator (fixed u).
NurbsSurface hourglass() {
  NurbsSurface s;
  s.nu = 9;
  s.uorder = 3;
  s.uknots.assign(kCircleKnots.begin(), kCircleKnots.end());
  s.nv = 3;
  s.vorder = 2;
  s.vknots = {0, 0, 1.25, 2, 2};
  const double profile[3][2] = {{1, -1}, {0, 0}, {1, 1}};
  for (const auto& [rho, z] : profile)
    for (const auto& [x, y, w] : circle(1)) s.pw.push_back({w * rho * x, w * rho * y, w * z, w});
  return s;
}

// The same surface with u and v exchanged: rows become columns (and the normals turn over).
NurbsSurface transposed(const NurbsSurface& s) {
  NurbsSurface t;
  t.nu = s.nv;
  t.uorder = s.vorder;
  t.uknots = s.vknots;
  t.nv = s.nu;
  t.vorder = s.uorder;
  t.vknots = s.uknots;
  for (int i = 0; i < s.nu; ++i)
    for (int j = 0; j < s.nv; ++j) t.pw.push_back(s.pw[size_t(j) * s.nu + i]);
  return t;
}

TEST(Nurbs, PolesOnAnInteriorKnotOrAtASubrangeEndFaceTheirPatch) {
  // The pinch's normals are the limit from the side the mesh takes it from: from the upper cone
  // over the whole range (an interior knot is evaluated from its right), from the lower cone
  // when the patch ends at it (v1 = 1.25), from the upper one when the patch starts at it. Each
  // equals the normal on its cone's generator one grid step away. Then the same with the pinch
  // as a column (u and v exchanged).
  struct Case {
    const char *name, *key;
    double v0, v1;
    int dice, pinch, neighbour;  // grid lines along v
  };
  const NurbsSurface rows = hourglass(), columns = transposed(rows);
  const int around = 9;  // vertices around the circle
  for (const Case& c : {Case{"whole range", "Whole", 0, 2, 9, 5, 6},
                        Case{"ends at the pinch", "Ending", 0, 1.25, 6, 5, 4},
                        Case{"starts at the pinch", "Starting", 1.25, 2, 4, 0, 1}}) {
    for (bool asColumn : {false, true}) {
      SCOPED_TRACE(fmt::format("{}, pinch as a {}", c.name, asColumn ? "column" : "row"));
      auto mesh = asColumn
                      ? makeNurbsMesh(Transform(), false, columns, c.v0, c.v1, 0, 1, c.dice, around)
                      : makeNurbsMesh(Transform(), false, rows, 0, 1, c.v0, c.v1, around, c.dice);
      auto at = [&](int line, int k) {
        return asColumn ? size_t(k) * c.dice + line : size_t(line) * around + k;
      };
      double worst = 0;
      int disagreeing = 0;
      for (int k = 0; k < around; ++k) {
        Normal3f pinch = mesh->n[at(c.pinch, k)], next = mesh->n[at(c.neighbour, k)];
        ASSERT_LT(Vector3f(mesh->p[at(c.pinch, k)]).length(), 1e-6f);
        worst = std::max(worst, double(Vector3f(pinch - next).length()));
        // The radial parts agree in sign: both face out (or, transposed, both in).
        Point3f q = mesh->p[at(c.neighbour, k)];
        disagreeing += !((pinch.x * q.x + pinch.y * q.y) * (next.x * q.x + next.y * q.y) > 0);
      }
      RecordProperty(fmt::format("maxPinchNormalError{}{}", c.key, asColumn ? "Column" : "Row"),
                     fmt::format("{:.3g}", worst));
      EXPECT_EQ(disagreeing, 0);
      // Both normals are the cone's exact one, rounded to float.
      EXPECT_LT(worst, 1e-6);
    }
  }
}

TEST(Nurbs, PointsBeyondFloatAreASceneErrorNotNaN) {
  // A weight of 1e-20 under x = 1e30 puts the point at 1e50: finite and positive, but no float.
  Patch p = planePatch(2, {0, 0, 1, 1}, 2, {0, 0, 1, 1});
  p.Pw = {1e30f, 0, 0, 1e-20f, 1, 0, 0, 1, 0, 1, 0, 1, 1, 1, 0, 1};
  p.P.clear();
  expectError(p, lineOf("Pw"), "\"Pw\" point 0 is at (1e+50, 0, 0), beyond float's range");
  // Control points that fit, moved out of float's range by the transform.
  Patch far = planePatch(2, {0, 0, 1, 1}, 2, {0, 0, 1, 1});
  for (Float& x : far.P) x = x * 1e30f + 1e30f;
  std::unique_ptr<TriangleMesh> mesh;
  try {
    createNurbsShapes(scale(1e10f, 1e10f, 1e10f), false, toParams(far), &mesh,
                      FileLoc{"nurbs.pbrt", kShapeLine, 1});
    ADD_FAILURE() << "the vertices are at ~1e40 in world space";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.location().line, lineOf("P")) << e.what();
    EXPECT_NE(std::string(e.what()).find("nurbs: the surface point at (u, v) = (0, 0) is not "
                                         "finite in float in world space"),
              std::string::npos)
        << e.what();
  }
}

TEST(Nurbs, FactoryErrorsForDiceLimitsAndNonFiniteParameters) {
  const Patch good = planePatch(2, {0, 0, 0.3f, 1, 1}, 3, {0, 0, 0, 1, 1, 1});
  auto with = [&](auto change) {
    Patch p = good;
    change(p);
    return p;
  };
  // 2^24 vertices at most; the error is at the larger of the two counts.
  expectError(with([](Patch& p) {
                p.ints = {{"diceu", 4096}, {"dicev", 4097}};
              }),
              lineOf("dicev"), "diceu * dicev = 4096 * 4097 = 16781312 vertices is too many");
  expectError(with([](Patch& p) {
                p.ints = {{"diceu", 8193}, {"dicev", 2048}};
              }),
              lineOf("diceu"), "diceu * dicev = 8193 * 2048 = 16779264 vertices is too many");
  // Equal counts, whose product overflows int: computed in 64 bits, the error at the first.
  expectError(with([](Patch& p) {
                p.ints = {{"diceu", 1 << 30}, {"dicev", 1 << 30}};
              }),
              lineOf("diceu"), "= 1073741824 * 1073741824 = 1152921504606846976 vertices");
  const Float inf = std::numeric_limits<Float>::infinity(),
              nan = std::numeric_limits<Float>::quiet_NaN();
  expectError(with([&](Patch& p) { p.uknots[2] = inf; }), lineOf("uknots"),
              "\"uknots\"[2] is not finite");
  expectError(with([&](Patch& p) { p.vknots[0] = -inf; }), lineOf("vknots"),
              "\"vknots\"[0] is not finite");
  expectError(with([&](Patch& p) { p.uknots[4] = nan; }), lineOf("uknots"),
              "\"uknots\"[4] is not finite");
  expectError(with([&](Patch& p) {
                p.floats = {{"u0", nan}};
              }),
              lineOf("u0"), "\"u0\" must be finite (got nan)", false);
  expectError(with([&](Patch& p) {
                p.floats = {{"v1", inf}};
              }),
              lineOf("v1"), "\"v1\" must be finite (got inf)", false);
  expectError(with([&](Patch& p) {
                p.Pw = {0, 0, 0, 1, 1, 0, 0, 1, 0, 1, 0, 1, 1, 1, 0, nan};
                p.nv = 2;
                p.vorder = 2;
                p.vknots = {0, 0, 1, 1};
                p.nu = 2;
                p.uknots = {0, 0, 1, 1};
                p.P.clear();
              }),
              lineOf("Pw"), "\"Pw\" point 3 is not finite");
}

}  // namespace
}  // namespace candela
