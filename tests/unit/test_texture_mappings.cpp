// Texture mappings (lrt draft §11.3): closed-form coordinates and their derivatives.
#include <gtest/gtest.h>

#include "core/paramset.h"
#include "support/param_items.h"
#include "textures/mapping.h"
#include "textures/texture_params.h"

using namespace candela;

namespace {

SurfaceInteraction at(const Point3f& p, const Vector3f& dpdx = Vector3f(),
                      const Vector3f& dpdy = Vector3f()) {
  SurfaceInteraction si;
  si.p = p;
  si.dpdx = dpdx;
  si.dpdy = dpdy;
  return si;
}

// Central-difference derivative of a mapping's (s, t) along d, for checking the exact ones.
Vector2f numeric(const TextureMapping2D& m, const Point3f& p, const Vector3f& d) {
  const Float h = 1e-3f;
  Point2f a = m.map(at(p + d * h)).st, b = m.map(at(p - d * h)).st;
  return Vector2f((a.x - b.x) / (2 * h), (a.y - b.y) / (2 * h));
}

}  // namespace

TEST(TextureMapping, UVScalesAndShifts) {
  SurfaceInteraction si;
  si.uv = Point2f(0.25f, 0.5f);
  si.dudx = 0.01f, si.dvdx = 0.02f, si.dudy = -0.03f, si.dvdy = 0.04f;
  TexCoord2D c = UVMapping2D(4, 2, 0.5f, -1).map(si);
  EXPECT_FLOAT_EQ(c.st.x, 4 * 0.25f + 0.5f);
  EXPECT_FLOAT_EQ(c.st.y, 2 * 0.5f - 1);
  EXPECT_FLOAT_EQ(c.dsdx, 0.04f);
  EXPECT_FLOAT_EQ(c.dtdx, 0.04f);
  EXPECT_FLOAT_EQ(c.dsdy, -0.12f);
  EXPECT_FLOAT_EQ(c.dtdy, 0.08f);
}

TEST(TextureMapping, SphericalClosedForm) {
  // s = theta / pi from +z, t = phi / 2pi from +x towards +y; centred on the texture origin.
  SphericalMapping2D m(translate(Vector3f(-1, -2, -3)));  // world (1, 2, 3) is the centre
  auto st = [&](Float x, Float y, Float z) { return m.map(at(Point3f(1 + x, 2 + y, 3 + z))).st; };
  EXPECT_NEAR(st(0, 0, 5).x, 0, 1e-6f);
  EXPECT_NEAR(st(0, 0, -2).x, 1, 1e-6f);
  EXPECT_NEAR(st(3, 0, 0).x, 0.5f, 1e-6f);
  EXPECT_NEAR(st(3, 0, 0).y, 0, 1e-6f);
  EXPECT_NEAR(st(0, 2, 0).y, 0.25f, 1e-6f);
  EXPECT_NEAR(st(-1, 0, 0).y, 0.5f, 1e-6f);
  EXPECT_NEAR(st(0, -1, 0).y, 0.75f, 1e-6f);
  EXPECT_NEAR(st(1, 1, std::sqrt(2.f)).x, 0.25f, 1e-6f);  // theta = 45 degrees
}

TEST(TextureMapping, SphericalDerivativesAreExactAndSeamFree) {
  SphericalMapping2D m((Transform()));
  Point3f p(0.6f, -0.3f, 0.9f);
  Vector3f dx(0.01f, 0.02f, -0.005f), dy(-0.003f, 0.004f, 0.02f);
  TexCoord2D c = m.map(at(p, dx, dy));
  Vector2f nx = numeric(m, p, dx), ny = numeric(m, p, dy);
  EXPECT_NEAR(c.dsdx, nx.x, 2e-4f);
  EXPECT_NEAR(c.dtdx, nx.y, 2e-4f);
  EXPECT_NEAR(c.dsdy, ny.x, 2e-4f);
  EXPECT_NEAR(c.dtdy, ny.y, 2e-4f);
  // Just below phi = 2pi a step across the seam changes t by a small amount, not by ~1.
  Point3f q(1, -1e-4f, 0.2f);
  TexCoord2D s = m.map(at(q, Vector3f(0, 0.01f, 0), Vector3f()));
  EXPECT_GT(s.st.y, 0.99f);
  EXPECT_NEAR(s.dtdx, 0.01f / (2 * kPi), 1e-5f);
  // On the pole t's derivative is 0 and s's is the sideways angle.
  TexCoord2D pole = m.map(at(Point3f(0, 0, 2), Vector3f(0.02f, 0, 0), Vector3f()));
  EXPECT_EQ(pole.dtdx, 0.f);
  EXPECT_NEAR(pole.dsdx, 0.01f / kPi, 1e-6f);
  // The centre itself maps to (0, 0) without NaN.
  TexCoord2D centre = m.map(at(Point3f(0, 0, 0), dx, dy));
  EXPECT_EQ(centre.st.x, 0.f);
  EXPECT_FALSE(std::isnan(centre.dsdx));
}

TEST(TextureMapping, CylindricalClosedFormAndDerivatives) {
  CylindricalMapping2D m((Transform()));
  auto st = [&](Float x, Float y, Float z) { return m.map(at(Point3f(x, y, z))).st; };
  EXPECT_NEAR(st(1, 0, 0).x, 0.5f, 1e-6f);
  EXPECT_NEAR(st(0, 1, 0).x, 0.75f, 1e-6f);
  EXPECT_NEAR(st(0, -1, 0).x, 0.25f, 1e-6f);
  EXPECT_NEAR(st(3, 0, 4).y, 0.8f, 1e-6f);  // z of the unit direction
  Point3f p(0.5f, 0.7f, -0.4f);
  Vector3f dx(0.01f, -0.02f, 0.03f);
  TexCoord2D c = m.map(at(p, dx, Vector3f()));
  Vector2f n = numeric(m, p, dx);
  EXPECT_NEAR(c.dsdx, n.x, 2e-4f);
  EXPECT_NEAR(c.dtdx, n.y, 2e-4f);
}

TEST(TextureMapping, PlanarIsExact) {
  Vector3f vs(1, 0.5f, 0), vt(0, 0, 2);
  PlanarMapping2D m(vs, vt, 0.25f, -0.5f, translate(Vector3f(1, 0, 0)));
  Point3f p(2, 3, 4);
  Vector3f dx(0.1f, 0.2f, 0.3f), dy(-0.4f, 0.5f, 0.6f);
  TexCoord2D c = m.map(at(p, dx, dy));
  EXPECT_FLOAT_EQ(c.st.x, 0.25f + (2 + 1) * 1 + 3 * 0.5f);
  EXPECT_FLOAT_EQ(c.st.y, -0.5f + 4 * 2);
  EXPECT_FLOAT_EQ(c.dsdx, dot(dx, vs));
  EXPECT_FLOAT_EQ(c.dtdx, dot(dx, vt));
  EXPECT_FLOAT_EQ(c.dsdy, dot(dy, vs));
  EXPECT_FLOAT_EQ(c.dtdy, dot(dy, vt));
}

TEST(TextureMapping, ThreeDimensionalTransformsPointAndDerivatives) {
  TextureMapping3D m(scale(2, 3, 4));
  TexCoord3D c = m.map(at(Point3f(1, 1, 1), Vector3f(1, 0, 0), Vector3f(0, 0, 0.5f)));
  EXPECT_EQ(c.p, Point3f(2, 3, 4));
  EXPECT_EQ(c.dpdx, Vector3f(2, 0, 0));
  EXPECT_EQ(c.dpdy, Vector3f(0, 0, 2));
}

TEST(TextureMapping, ParametersWithBothNamings) {
  SurfaceInteraction si;
  si.uv = Point2f(1, 1);
  ParamSet v2;
  v2.add(test::floats("uscale", {3}));
  v2.add(test::floats("vdelta", {0.5f}));
  Point2f a = createMapping2D(v2, Transform(), FileLoc{})->map(si).st;
  EXPECT_EQ(a, Point2f(3, 1.5f));
  ParamSet lrt;
  lrt.add(test::floats("su", {3}));
  lrt.add(test::floats("dv", {0.5f}));
  EXPECT_EQ(createMapping2D(lrt, Transform(), FileLoc{})->map(si).st, Point2f(3, 1.5f));

  ParamSet planar;
  planar.add(test::strings("mapping", {"planar"}));
  planar.add(test::vectors("v1", {0, 1, 0}));
  si.p = Point3f(5, 7, 9);
  EXPECT_EQ(createMapping2D(planar, Transform(), FileLoc{})->map(si).st, Point2f(7, 7));

  ParamSet bad;
  bad.add(test::strings("mapping", {"cubic"}, FileLoc{"m.pbrt", 4, 2}));
  try {
    createMapping2D(bad, Transform(), FileLoc{});
    FAIL();
  } catch (const SceneError& e) {
    std::string m = e.what();
    EXPECT_NE(m.find("m.pbrt:4:2"), std::string::npos) << m;
    EXPECT_NE(m.find("cubic"), std::string::npos) << m;
    EXPECT_NE(m.find("spherical"), std::string::npos) << m;
  }
}
