// Transforms and their inverses (lrt draft §2.7).
#include <gtest/gtest.h>

#include "core/rng.h"
#include "core/transform.h"

namespace candela {
namespace {

void expectIdentity(const Matrix4x4& m, double tol) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(m.m[i][j], i == j ? 1 : 0, tol) << i << "," << j;
}

TEST(Transform, ComposedTransformTimesInverseIsIdentity) {
  Transform t = translate(Vector3f(1, -2, 3)) * rotate(33, Vector3f(1, 1, 0.2f)) *
                scale(2, 0.5f, -3) * rotateX(10) * rotateY(-70) * rotateZ(5);
  expectIdentity(mul(t.matrix(), t.inverseMatrix()), 1e-5);
  Matrix4x4 inv;
  ASSERT_TRUE(inverse(t.matrix(), &inv));
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(inv.m[i][j], t.inverseMatrix().m[i][j], 1e-5);
}

TEST(Transform, SingularMatrixIsReported) {
  Matrix4x4 m(1, 2, 3, 0, 2, 4, 6, 0, 0, 0, 1, 0, 0, 0, 0, 1);
  Matrix4x4 inv;
  EXPECT_FALSE(inverse(m, &inv));
  EXPECT_THROW(Transform{m}, std::domain_error);
  EXPECT_THROW(scale(0, 1, 1), std::domain_error);
  EXPECT_THROW(rotate(10, Vector3f(0, 0, 0)), std::domain_error);
}

TEST(Transform, RotationInverseIsTranspose) {
  Transform r = rotate(47, Vector3f(0.3f, -1, 2));
  Matrix4x4 t = transpose(r.matrix());
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(t.m[i][j], r.inverseMatrix().m[i][j], 1e-6);
  // Rotate 90 about z takes x to y.
  Vector3f v = rotateZ(90)(Vector3f(1, 0, 0));
  EXPECT_NEAR(v.x, 0, 1e-6);
  EXPECT_NEAR(v.y, 1, 1e-6);
}

TEST(Transform, PointsVectorsAndNormals) {
  Transform t = translate(Vector3f(5, 0, 0)) * scale(2, 1, 1);
  EXPECT_EQ(t(Point3f(1, 1, 1)), Point3f(7, 1, 1));
  EXPECT_EQ(t(Vector3f(1, 1, 1)), Vector3f(2, 1, 1));  // no translation
  // A normal stays perpendicular to a tangent under non-uniform scale.
  Vector3f tangent(1, -1, 0);
  Normal3f n(1, 1, 0);
  EXPECT_NEAR(dot(t(n), t(tangent)), 0, 1e-6);
  EXPECT_TRUE(scale(-1, 1, 1).swapsHandedness());
  EXPECT_FALSE(rotate(30, Vector3f(1, 2, 3)).swapsHandedness());
}

TEST(Transform, LookAtMapsTheViewDirectionToPlusZ) {
  Point3f eye(1, 2, 3), look(4, -2, 7);
  Transform worldToCamera = lookAt(eye, look, Vector3f(0, 1, 0));
  Point3f e = worldToCamera(eye);
  EXPECT_NEAR(e.x, 0, 1e-5);
  EXPECT_NEAR(e.y, 0, 1e-5);
  EXPECT_NEAR(e.z, 0, 1e-5);
  Vector3f d = worldToCamera(normalize(look - eye));
  EXPECT_NEAR(d.z, 1, 1e-5);
  // Up stays up (positive camera y).
  EXPECT_GT(worldToCamera(Vector3f(0, 1, 0)).y, 0);
  EXPECT_THROW(lookAt(eye, eye, Vector3f(0, 1, 0)), std::domain_error);
  EXPECT_THROW(lookAt(Point3f(0, 0, 0), Point3f(0, 1, 0), Vector3f(0, 1, 0)), std::domain_error);
}

TEST(Transform, ErrorBoundsContainTheExactResult) {
  RNG rng(9);
  Transform t =
      translate(Vector3f(1e3f, -2e2f, 5)) * rotate(17, Vector3f(1, 2, 3)) * scale(3, 0.1f, 7);
  for (int i = 0; i < 10000; ++i) {
    Point3f p((rng.uniformFloat() - 0.5f) * 2e3f, (rng.uniformFloat() - 0.5f) * 10,
              rng.uniformFloat() * 1e4f);
    Vector3f err;
    Point3f r = t.apply(p, &err);
    const auto& m = t.matrix().m;
    for (int a = 0; a < 3; ++a) {
      long double exact = (long double)m[a][0] * p.x + (long double)m[a][1] * p.y +
                          (long double)m[a][2] * p.z + m[a][3];
      ASSERT_LE(std::abs((long double)r[a] - exact), (long double)err[a]) << i << " axis " << a;
    }
  }
}

TEST(Transform, PerspectiveMapsFovEdgeToScreenEdge) {
  Transform p = perspective(90, 0.01f, 1000);
  Point3f q = p(Point3f(1, 0, 1));  // 45 degrees off axis
  EXPECT_NEAR(q.x, 1, 1e-5);
  EXPECT_NEAR(p(Point3f(0, 0, 0.01f)).z, 0, 1e-5);
  EXPECT_NEAR(p(Point3f(0, 0, 1000)).z, 1, 1e-5);
}

}  // namespace
}  // namespace candela
