// Sphere, cylinder, disk, cone, paraboloid, hyperboloid: analytic hits, partial-sweep clipping,
// differential geometry against an independent model of each parameterisation (quadric_models.h),
// orientation under ReverseOrientation and mirrors, singular points, bad rays, factories.
#include <gtest/gtest.h>

#include "core/rng.h"
#include "core/sampling.h"
#include "quadric_models.h"
#include "support/geometry_expect.h"
#include "support/param_items.h"

namespace candela {
namespace {

using test::D3;
using test::QuadricModel;

Vector3f toVec(const D3& v) { return Vector3f(Float(v[0]), Float(v[1]), Float(v[2])); }

D3 worldPoint(const Transform& t, const D3& p) {
  const auto& m = t.matrix().m;
  D3 q;
  for (int i = 0; i < 3; ++i)
    q[i] = double(m[i][0]) * p[0] + double(m[i][1]) * p[1] + double(m[i][2]) * p[2] + m[i][3];
  return q;
}
D3 worldVector(const Transform& t, const D3& v) {
  const auto& m = t.matrix().m;
  D3 q;
  for (int i = 0; i < 3; ++i)
    q[i] = double(m[i][0]) * v[0] + double(m[i][1]) * v[1] + double(m[i][2]) * v[2];
  return q;
}
// The model's outward normal at (u, v) in world space: M^-T n, normalised.
D3 worldOutward(const QuadricModel& m, const Transform& t, double u, double v) {
  D3 n = m.outward(u, v);
  const auto& mi = t.inverseMatrix().m;
  D3 w;
  for (int i = 0; i < 3; ++i)
    w[i] = double(mi[0][i]) * n[0] + double(mi[1][i]) * n[1] + double(mi[2][i]) * n[2];
  return test::scaleD(w, 1 / test::lenD(w));
}

Float uniform(RNG& rng, Float a, Float b) { return a + (b - a) * rng.uniformFloat(); }

// Parameters in [lo, hi]^2, away from an apex inside the range (where hitAt's offset origin could
// be across the axis).
void randomUV(RNG& rng, const QuadricModel& m, Float lo, Float hi, double* u, double* v) {
  do {
    *u = uniform(rng, lo, hi);
    *v = uniform(rng, lo, hi);
  } while (std::abs(*v - m.apexV) < 0.02);
}

// A hit on the model's point (u, v), from a point off the surface along the outward normal.
bool hitAt(const Shape& s, const QuadricModel& m, const Transform& t, double u, double v,
           SurfaceInteraction* isect) {
  D3 target = worldPoint(t, m.P(u, v));
  D3 n = worldOutward(m, t, u, v);
  Point3f o(Float(target[0] + 1e-3 * n[0]), Float(target[1] + 1e-3 * n[1]),
            Float(target[2] + 1e-3 * n[2]));
  Vector3f d(Float(target[0] - o.x), Float(target[1] - o.y), Float(target[2] - o.z));
  Float tHit;
  return s.intersect(Ray(o, d * 2), &tHit, isect);
}

const std::vector<Transform>& transforms() {
  static const std::vector<Transform> ts = {
      Transform(),
      translate(Vector3f(0.5f, -2, 3)) * rotate(37, Vector3f(1, 2, 0.5f)) * scale(2, 2, 2),
      rotateX(20) * scale(1.5f, 0.6f, 1.1f), scale(-1, 1, 1) * rotateY(50)};
  return ts;
}

TEST(Quadrics, AnalyticHits) {
  Float t;
  SurfaceInteraction si;
  // Cylinder r = 2: from x = 5 inward, t = 3; from the axis outward, t = 2, normal along the ray.
  CylinderShape cyl(Transform(), false, 2, -1, 1, 360);
  ASSERT_TRUE(cyl.intersect(Ray(Point3f(5, 0, 0.5f), Vector3f(-1, 0, 0)), &t, &si));
  EXPECT_NEAR(t, 3, 1e-6);
  test::expectNear(Vector3f(si.n), Vector3f(1, 0, 0), 1e-5f);
  ASSERT_TRUE(cyl.intersect(Ray(Point3f(0, 0, 0), Vector3f(0, 1, 0)), &t, &si));
  EXPECT_NEAR(t, 2, 1e-6);
  test::expectNear(Vector3f(si.n), Vector3f(0, 1, 0), 1e-5f);
  EXPECT_FALSE(cyl.intersectP(Ray(Point3f(0, 0, 5), Vector3f(0, 0, -1))));     // along the axis
  EXPECT_FALSE(cyl.intersectP(Ray(Point3f(5, 0, 1.5f), Vector3f(-1, 0, 0))));  // above zmax

  // Disk at z = 1, r = 2, ri = 0.5: t = 4, normal +z; the hole and the outside miss.
  DiskShape disk(Transform(), false, 1, 2, 0.5f, 360);
  ASSERT_TRUE(disk.intersect(Ray(Point3f(0.5f, 0.5f, 5), Vector3f(0, 0, -1)), &t, &si));
  EXPECT_NEAR(t, 4, 1e-6);
  test::expectNear(Vector3f(si.n), Vector3f(0, 0, 1), 1e-6f);
  EXPECT_FALSE(disk.intersectP(Ray(Point3f(0.2f, 0, 5), Vector3f(0, 0, -1))));
  EXPECT_FALSE(disk.intersectP(Ray(Point3f(2.1f, 0, 5), Vector3f(0, 0, -1))));
  EXPECT_FALSE(disk.intersectP(Ray(Point3f(0, 0, 1), Vector3f(1, 0, 0))));  // in its plane

  // Cone r = 1, h = 2: radius 0.5 at z = 1, normal (h, 0, r) / sqrt(5).
  ConeShape cone(Transform(), false, 2, 1, 360);
  ASSERT_TRUE(cone.intersect(Ray(Point3f(5, 0, 1), Vector3f(-1, 0, 0)), &t, &si));
  EXPECT_NEAR(t, 4.5f, 1e-6);
  test::expectNear(Vector3f(si.n), Vector3f(2, 0, 1) / std::sqrt(5.f), 1e-5f);
  EXPECT_NEAR(si.uv.y, 0.5f, 1e-6);
  EXPECT_FALSE(cone.intersectP(Ray(Point3f(5, 0, 2.5f), Vector3f(-1, 0, 0))));  // other nappe

  // Paraboloid r = 1, zmax = 1: radius 0.5 at z = 0.25, normal (1, 0, -1) / sqrt(2).
  ParaboloidShape par(Transform(), false, 1, 0, 1, 360);
  ASSERT_TRUE(par.intersect(Ray(Point3f(5, 0, 0.25f), Vector3f(-1, 0, 0)), &t, &si));
  EXPECT_NEAR(t, 4.5f, 1e-6);
  test::expectNear(Vector3f(si.n), Vector3f(1, 0, -1) / std::sqrt(2.f), 1e-5f);

  // Hyperboloid p1 = (1, 0, -1), p2 = (0, 1, 1): at z = 0 the segment point is (0.5, 0.5, 0),
  // radius sqrt(1/2), the waist, where the normal is radial.
  HyperboloidShape hyp(Transform(), false, Point3f(1, 0, -1), Point3f(0, 1, 1), 360);
  ASSERT_TRUE(hyp.intersect(Ray(Point3f(5, 0, 0), Vector3f(-1, 0, 0)), &t, &si));
  EXPECT_NEAR(t, 5 - std::sqrt(0.5f), 1e-6);
  test::expectNear(Vector3f(si.n), Vector3f(1, 0, 0), 1e-5f);
  EXPECT_NEAR(si.uv.y, 0.5f, 1e-6);
  // (0.5, 0.5) turned to (sqrt(1/2), 0) is a rotation by -45 degrees, i.e. 315 degrees.
  EXPECT_NEAR(si.uv.x, 315.f / 360, 1e-5);
}

TEST(Quadrics, PartialSweepUsesFarRoot) {
  Float t;
  SurfaceInteraction si;
  // phimax = 90: a ray along +x at y = 0.5 meets x < 0 first (phi ~ 150, clipped), then x > 0.
  CylinderShape cyl(Transform(), false, 1, -1, 1, 90);
  ASSERT_TRUE(cyl.intersect(Ray(Point3f(-5, 0.5f, 0), Vector3f(1, 0, 0)), &t, &si));
  EXPECT_NEAR(si.p.x, std::sqrt(0.75f), 1e-5);
  EXPECT_FALSE(cyl.intersectP(Ray(Point3f(-5, -0.5f, 0), Vector3f(1, 0, 0))));
  ConeShape cone(Transform(), false, 1, 1, 90);
  ASSERT_TRUE(cone.intersect(Ray(Point3f(-5, 0.25f, 0.5f), Vector3f(1, 0, 0)), &t, &si));
  EXPECT_GT(si.p.x, 0);
  ParaboloidShape par(Transform(), false, 1, 0, 1, 90);
  ASSERT_TRUE(par.intersect(Ray(Point3f(-5, 0.25f, 0.5f), Vector3f(1, 0, 0)), &t, &si));
  EXPECT_GT(si.p.x, 0);
  DiskShape disk(Transform(), false, 0, 1, 0, 90);
  EXPECT_TRUE(disk.intersectP(Ray(Point3f(0.5f, 0.5f, 1), Vector3f(0, 0, -1))));
  EXPECT_FALSE(disk.intersectP(Ray(Point3f(-0.5f, 0.5f, 1), Vector3f(0, 0, -1))));
  // z range: a cylinder cut at zmax = 0 seen from above and outside-in through its wall.
  CylinderShape low(Transform(), false, 1, -1, 0, 360);
  ASSERT_TRUE(low.intersect(Ray(Point3f(-5, 0, 2.5f), Vector3f(1, 0, -0.5f)), &t, &si));
  // Passes x = -1 at z = 0.5, above the cut, and hits the far wall inside at z = -0.5.
  EXPECT_NEAR(si.p.x, 1, 1e-5);
  EXPECT_NEAR(si.p.z, -0.5f, 1e-5);
}

// Every hit of a partial shape is the first hit of the full shape whose angle is in range: the
// full shape's first two hits are found by continuing past the first.
TEST(Quadrics, PartialSweepClipsExactly) {
  struct Pair {
    std::unique_ptr<Quadric> partial, full;
    double phiMax;
  };
  Transform t = rotate(25, Vector3f(1, 1, 0));
  std::vector<Pair> pairs;
  pairs.push_back({std::make_unique<SphereShape>(t, false, 1, -0.8f, 0.9f, 230),
                   std::make_unique<SphereShape>(t, false, 1, -0.8f, 0.9f, 360), 230});
  pairs.push_back({std::make_unique<CylinderShape>(t, false, 1, -1, 1, 200),
                   std::make_unique<CylinderShape>(t, false, 1, -1, 1, 360), 200});
  pairs.push_back({std::make_unique<DiskShape>(t, false, 0.2f, 1, 0.3f, 120),
                   std::make_unique<DiskShape>(t, false, 0.2f, 1, 0.3f, 360), 120});
  pairs.push_back({std::make_unique<ConeShape>(t, false, 1.5f, 1, 250),
                   std::make_unique<ConeShape>(t, false, 1.5f, 1, 360), 250});
  pairs.push_back({std::make_unique<ParaboloidShape>(t, false, 1, 0.1f, 1, 300),
                   std::make_unique<ParaboloidShape>(t, false, 1, 0.1f, 1, 360), 300});
  pairs.push_back(
      {std::make_unique<HyperboloidShape>(t, false, Point3f(1, 0, -1), Point3f(0, 1, 1), 150),
       std::make_unique<HyperboloidShape>(t, false, Point3f(1, 0, -1), Point3f(0, 1, 1), 360),
       150});
  RNG rng(11);
  for (const Pair& pair : pairs) {
    int partialHits = 0;
    for (int i = 0; i < 4000; ++i) {
      Point3f o(uniform(rng, -3, 3), uniform(rng, -3, 3), uniform(rng, -3, 3));
      Point3f target(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
      Ray ray(o, target - o);
      // The full shape's hits in order, up to two, with their sweep angles (the full shape's
      // u = phi / 360 degrees; for the hyperboloid the angle the segment turned).
      std::vector<std::pair<Float, double>> hits;
      Ray r = ray;
      for (int k = 0; k < 2; ++k) {
        Float th;
        SurfaceInteraction si;
        if (!pair.full->intersect(r, &th, &si)) break;
        hits.push_back({(si.p - ray.o).length() / ray.d.length(), si.uv.x * 360.0});
        r = si.spawnRay(ray.d);
      }
      Float expectedT = -1;
      for (auto& [th, phi] : hits) {
        // Angles within rounding of phiMax are ambiguous; skip such rays.
        if (std::abs(phi - pair.phiMax) < 1e-3) {
          expectedT = -2;
          break;
        }
        if (phi <= pair.phiMax) {
          expectedT = th;
          break;
        }
      }
      if (expectedT == -2) continue;
      Float th;
      bool hit = pair.partial->intersect(ray, &th, nullptr);
      if (expectedT < 0) {
        EXPECT_FALSE(hit) << pair.full->kind() << " ray " << i;
      } else {
        ++partialHits;
        ASSERT_TRUE(hit) << pair.full->kind() << " ray " << i;
        EXPECT_NEAR(th, expectedT, 1e-4f * expectedT) << pair.full->kind() << " ray " << i;
      }
    }
    EXPECT_GT(partialHits, 200) << pair.full->kind();
  }
}

TEST(Quadrics, DifferentialGeometryMatchesModel) {
  RNG rng(12);
  for (const QuadricModel& m : test::allModels()) {
    for (const Transform& t : transforms()) {
      std::unique_ptr<Quadric> s = m.make(t, false);
      for (int i = 0; i < 200; ++i) {
        double u, v;
        randomUV(rng, m, 0.02f, 0.98f, &u, &v);
        SurfaceInteraction si;
        ASSERT_TRUE(hitAt(*s, m, t, u, v, &si)) << m.name << " at " << u << ", " << v;
        std::string where = m.name + " at (" + std::to_string(u) + ", " + std::to_string(v) + ")";
        EXPECT_NEAR(si.uv.x, u, 1e-4) << where;
        EXPECT_NEAR(si.uv.y, v, 1e-4) << where;
        D3 pw = worldPoint(t, m.P(u, v));
        Float scale = Float(m.size * 4);
        test::expectNear(Vector3f(si.p), toVec(pw), 1e-5f * scale);
        // Outward normal and the tangents of the parameterisation.
        EXPECT_GT(dot(si.n, toVec(worldOutward(m, t, u, v))), 0.9999f) << where;
        Vector3f dpdu = toVec(worldVector(t, m.dPdu(u, v))),
                 dpdv = toVec(worldVector(t, m.dPdv(u, v)));
        test::expectNear(si.dpdu, dpdu, 1e-4f * std::max(Float(1), dpdu.length()));
        test::expectNear(si.dpdv, dpdv, 1e-4f * std::max(Float(1), dpdv.length()));
      }
    }
  }
}

TEST(Quadrics, NormalDerivativesMatchFiniteDifferences) {
  // dn/du and dn/dv (Weingarten, lrt draft §3.2.4) against central differences of the model's
  // world-space unit normal, under similarity and non-uniform transforms.
  RNG rng(13);
  for (const QuadricModel& m : test::allModels()) {
    for (const Transform& t : transforms()) {
      std::unique_ptr<Quadric> s = m.make(t, false);
      for (int i = 0; i < 100; ++i) {
        double u, v;
        randomUV(rng, m, 0.05f, 0.95f, &u, &v);
        SurfaceInteraction si;
        ASSERT_TRUE(hitAt(*s, m, t, u, v, &si));
        const double h = 1e-4;
        D3 dndu = test::scaleD(
            test::sub(worldOutward(m, t, u + h, v), worldOutward(m, t, u - h, v)), 0.5 / h);
        D3 dndv = test::scaleD(
            test::sub(worldOutward(m, t, u, v + h), worldOutward(m, t, u, v - h)), 0.5 / h);
        // Relative to the normal's rate of turning along each parameter line (dn/du of a cylinder
        // is phiMax in size; a disk's is 0).
        Float tolU = 2e-3f * std::max(Float(1), Float(test::lenD(dndu)));
        Float tolV = 2e-3f * std::max(Float(1), Float(test::lenD(dndv)));
        std::string where = m.name + " at (" + std::to_string(u) + ", " + std::to_string(v) + ")";
        SCOPED_TRACE(where);
        test::expectNear(Vector3f(si.dndu), toVec(dndu), tolU);
        test::expectNear(Vector3f(si.dndv), toVec(dndv), tolV);
      }
    }
  }
}

TEST(Quadrics, OrientationUnderReverseAndMirrors) {
  RNG rng(14);
  for (const QuadricModel& m : test::allModels()) {
    for (const Transform& t : transforms()) {
      for (bool reverse : {false, true}) {
        std::unique_ptr<Quadric> s = m.make(t, reverse);
        Float sign = reverse ? -1 : 1;
        for (int i = 0; i < 50; ++i) {
          double u, v;
          randomUV(rng, m, 0.02f, 0.98f, &u, &v);
          SurfaceInteraction si;
          ASSERT_TRUE(hitAt(*s, m, t, u, v, &si));
          Vector3f out = toVec(worldOutward(m, t, u, v));
          EXPECT_GT(sign * dot(si.n, out), 0.9999f) << m.name << " reverse " << reverse;
          EXPECT_GT(sign * dot(si.shading.n, out), 0.9999f);
          Float pdf;
          Interaction it = s->sample(Point2f(Float(u), Float(v)), &pdf);
          Point2f uv = m.uvOf(test::toObject(t, it.p));
          EXPECT_GT(sign * dot(it.n, toVec(worldOutward(m, t, uv.x, uv.y))), 0.9999f)
              << m.name << " sample, reverse " << reverse;
        }
      }
    }
  }
}

void expectFinite(const SurfaceInteraction& si, const std::string& what) {
  EXPECT_FALSE(si.dpdu.hasNaN() || si.dpdv.hasNaN() || si.dndu.hasNaN() || si.dndv.hasNaN() ||
               si.n.hasNaN() || si.p.hasNaN())
      << what;
  EXPECT_GT(si.dpdu.lengthSquared(), 0) << what;
  EXPECT_GT(si.dpdv.lengthSquared(), 0) << what;
  EXPECT_NEAR(Vector3f(si.n).length(), 1, 1e-5) << what;
  EXPECT_TRUE(std::isfinite(si.uv.x) && std::isfinite(si.uv.y)) << what;
}

TEST(Quadrics, SingularPointsAreFinite) {
  // The draft's dp/dv / (1 - v) at the disk centre and cone apex, and the paraboloid's and a
  // through-axis hyperboloid's apex (seed notes §23, §24).
  Float t;
  SurfaceInteraction si;
  DiskShape disk(Transform(), false, 0, 1, 0, 360);
  ASSERT_TRUE(disk.intersect(Ray(Point3f(0, 0, 1), Vector3f(0, 0, -1)), &t, &si));
  expectFinite(si, "disk centre");
  test::expectNear(Vector3f(si.n), Vector3f(0, 0, 1), 1e-6f);
  EXPECT_NEAR(si.uv.y, 1, 1e-6);
  ConeShape cone(Transform(), false, 1, 1, 360);
  ASSERT_TRUE(cone.intersect(Ray(Point3f(0, 0, 3), Vector3f(0, 0.001f, -1)), &t, &si));
  expectFinite(si, "near the cone apex");
  ASSERT_TRUE(cone.intersect(Ray(Point3f(-2, 0, 1), Vector3f(1, 0, 0)), &t, &si));
  EXPECT_NEAR(si.p.x, 0, 1e-6);
  expectFinite(si, "cone apex");
  ParaboloidShape par(Transform(), false, 1, 0, 1, 360);
  ASSERT_TRUE(par.intersect(Ray(Point3f(0, 0, -1), Vector3f(0, 0, 1)), &t, &si));
  expectFinite(si, "paraboloid apex");
  test::expectNear(Vector3f(si.n), Vector3f(0, 0, -1), 1e-4f);
  HyperboloidShape hyp(Transform(), false, Point3f(1, 0, -1), Point3f(-1, 0, 1), 360);
  ASSERT_TRUE(hyp.intersect(Ray(Point3f(-3, 0, 0), Vector3f(1, 0, 0)), &t, &si));
  EXPECT_NEAR(si.p.x, 0, 1e-6);
  expectFinite(si, "hyperboloid apex");
}

TEST(Quadrics, RejectsBadRays) {
  Float nan = std::numeric_limits<Float>::quiet_NaN();
  for (const QuadricModel& m : test::allModels()) {
    std::unique_ptr<Quadric> s = m.make(Transform(), false);
    Float t;
    for (const Ray& r : {Ray(Point3f(nan, 0, -5), Vector3f(0, 0, 1)),
                         Ray(Point3f(0.1f, 0.2f, -5), Vector3f(0, nan, 1)),
                         Ray(Point3f(0.1f, 0.2f, -5), Vector3f(0, 0, 0)),
                         Ray(Point3f(0.1f, 0.2f, -kInfinity), Vector3f(0, 0, 1)),
                         Ray(Point3f(0.1f, 0.2f, -5), Vector3f(0, kInfinity, 1)),
                         Ray(Point3f(0.1f, 0.2f, -5), Vector3f(0, 0, 1), nan)}) {
      EXPECT_FALSE(s->intersect(r, &t, nullptr)) << m.name;
      EXPECT_FALSE(s->intersectP(r)) << m.name;
    }
  }
}

TEST(Quadrics, ZeroAreaShapesAreNeverHit) {
  CylinderShape flat(Transform(), false, 1, 0.5f, 0.5f, 360);
  EXPECT_EQ(flat.area(), 0);
  EXPECT_FALSE(flat.intersectP(Ray(Point3f(-5, 0, 0.5f), Vector3f(1, 0, 0))));
  DiskShape ring(Transform(), false, 0, 1, 1, 360);
  EXPECT_FALSE(ring.intersectP(Ray(Point3f(1, 0, 1), Vector3f(0, 0, -1))));
  Float pdf;
  ring.sample(Point2f(0.5f, 0.5f), &pdf);
  EXPECT_EQ(pdf, 0);
}

// Where the parameters of the failing cases are written: the errors must point there.
const FileLoc kBadLoc{"scene.pbrt", 9, 4};

void expectSceneError(const std::function<void()>& f, const std::string& word) {
  try {
    f();
    ADD_FAILURE() << "expected a SceneError about " << word;
  } catch (const SceneError& e) {
    EXPECT_EQ(e.location().line, 9) << e.what();
    EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
  }
}

TEST(Quadrics, FactoryDefaults) {
  // pbrt-v2's defaults and their areas in closed form.
  ParamSet none;
  EXPECT_NEAR(createCylinderShape(Transform(), false, none)->area(), 4 * kPi, 1e-5);
  EXPECT_NEAR(createDiskShape(Transform(), false, none)->area(), kPi, 1e-6);
  EXPECT_NEAR(createConeShape(Transform(), false, none)->area(), kPi * std::sqrt(2.f), 1e-5);
  EXPECT_NEAR(createParaboloidShape(Transform(), false, none)->area(),
              kPi / 6 * (5 * std::sqrt(5.f) - 1), 1e-5);
  // p1 = 0, p2 = (1, 1, 1): a cone with apex at the origin, radius sqrt 2, slant sqrt 3.
  EXPECT_NEAR(createHyperboloidShape(Transform(), false, none)->area(), kPi * std::sqrt(6.f), 1e-5);
  EXPECT_STREQ(createHyperboloidShape(Transform(), false, none)->kind(), "hyperboloid");
}

TEST(Quadrics, FactoryParameters) {
  ParamSet ps;
  ps.add(test::floats("radius", {2}));
  ps.add(test::floats("zmin", {-0.5f}));
  ps.add(test::floats("zmax", {1}));
  ps.add(test::floats("thetamax", {180}));  // the lrt draft's name for phimax
  auto s = createCylinderShape(Transform(), false, ps);
  EXPECT_STREQ(s->kind(), "cylinder");
  EXPECT_NEAR(s->area(), 1.5f * kPi * 2, 1e-5);
  ps.forEachUnused([](const ParamItem& item) { ADD_FAILURE() << item.name << " unused"; });

  ParamSet disk;
  disk.add(test::floats("height", {1}));
  disk.add(test::floats("radius", {2}));
  disk.add(test::floats("innerradius", {1}));
  disk.add(test::floats("phimax", {90}));
  EXPECT_NEAR(createDiskShape(Transform(), false, disk)->area(), kPiOver4 * 3, 1e-5);
  disk.forEachUnused([](const ParamItem& item) { ADD_FAILURE() << item.name << " unused"; });

  ParamSet hyp;
  hyp.add(test::points("p1", {1, 0, 0}));
  hyp.add(test::points("p2", {1, 0, 2}));
  EXPECT_NEAR(createHyperboloidShape(Transform(), false, hyp)->area(), 4 * kPi, 1e-5);  // cylinder
}

TEST(Quadrics, FactoryErrors) {
  auto with = [](const std::string& name, std::vector<Float> v) {
    ParamSet ps;
    ps.add(test::floats(name, std::move(v), kBadLoc));
    return ps;
  };
  expectSceneError([&] { createCylinderShape(Transform(), false, with("radius", {-1})); },
                   "radius");
  expectSceneError([&] { createDiskShape(Transform(), false, with("innerradius", {1})); },
                   "innerradius");
  expectSceneError([&] { createConeShape(Transform(), false, with("height", {0})); }, "height");
  expectSceneError([&] { createParaboloidShape(Transform(), false, with("zmax", {-1})); }, "zmax");
  expectSceneError([&] { createCylinderShape(Transform(), false, with("zmax", {kInfinity})); },
                   "zmax");
  ParamSet hyp;
  hyp.add(test::points("p1", {0, 0, 1}, kBadLoc));
  hyp.add(test::points("p2", {1, 0, 1}, kBadLoc));
  expectSceneError([&] { createHyperboloidShape(Transform(), false, hyp); }, "differ in z");
}

}  // namespace
}  // namespace candela
