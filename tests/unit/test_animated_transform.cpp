// Animated transforms (pbrt 2e §2.9.3): polar decomposition round trip, exact end points, slerp
// at constant angular speed, and motion bounds that contain the moving box.
#include <gtest/gtest.h>

#include "core/animated_transform.h"
#include "core/rng.h"

namespace candela {
namespace {

void expectMatrixNear(const Matrix4x4& a, const Matrix4x4& b, double tol) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(a.m[i][j], b.m[i][j], tol) << i << "," << j;
}

Transform randomAffine(RNG& rng, bool mirror) {
  auto u = [&](Float lo, Float hi) { return lerp(rng.uniformFloat(), lo, hi); };
  Vector3f axis(u(-1, 1), u(-1, 1), u(-1, 1) + 2);
  Transform t = translate(Vector3f(u(-10, 10), u(-10, 10), u(-10, 10))) *
                rotate(u(-180, 180), axis) * scale(u(0.2f, 4), u(0.2f, 4), u(0.2f, 4)) *
                rotate(u(-90, 90), Vector3f(u(-1, 1), 1, u(-1, 1)));
  return mirror ? t * scale(-1, 1, 1) : t;
}

TEST(AnimatedTransform, DecompositionRoundTrip) {
  RNG rng(7);
  for (int k = 0; k < 200; ++k) {
    Transform t = randomAffine(rng, k % 2 == 1);
    TransformComponents c = decompose(t.matrix());
    // R is a unit quaternion, S is symmetric, and T R S gives the matrix back.
    EXPECT_NEAR(c.rotation.length(), 1, 1e-12);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(c.stretch[i][j], c.stretch[j][i], 1e-5);
    Matrix4x4 m = compose(c);
    Float scaleOfM = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 4; ++j) scaleOfM = std::max(scaleOfM, std::abs(t.matrix().m[i][j]));
    expectMatrixNear(m, t.matrix(), 1e-6 * scaleOfM);
  }
}

TEST(AnimatedTransform, DecompositionSeparatesKnownParts) {
  Transform t = translate(Vector3f(1, 2, 3)) * rotateZ(30) * scale(2, 3, 4);
  TransformComponents c = decompose(t.matrix());
  EXPECT_NEAR(c.translation[0], 1, 1e-6);
  EXPECT_NEAR(c.translation[1], 2, 1e-6);
  EXPECT_NEAR(c.translation[2], 3, 1e-6);
  // Rotation by 30 degrees about z: (0, 0, sin 15, cos 15) up to sign.
  Float sign = c.rotation.w < 0 ? -1 : 1;
  EXPECT_NEAR(sign * c.rotation.z, std::sin(radians(15)), 1e-6);
  EXPECT_NEAR(sign * c.rotation.w, std::cos(radians(15)), 1e-6);
  EXPECT_NEAR(c.stretch[0][0], 2, 1e-5);
  EXPECT_NEAR(c.stretch[1][1], 3, 1e-5);
  EXPECT_NEAR(c.stretch[2][2], 4, 1e-5);
  EXPECT_NEAR(c.stretch[0][1], 0, 1e-5);
}

TEST(AnimatedTransform, EndPointsAreExactAndTimeIsClamped) {
  RNG rng(11);
  Transform a = randomAffine(rng, false), b = randomAffine(rng, false);
  AnimatedTransform at(a, 2, b, 5);
  ASSERT_TRUE(at.isAnimated());
  EXPECT_EQ(at.interpolate(2).matrix(), a.matrix());
  EXPECT_EQ(at.interpolate(2).inverseMatrix(), a.inverseMatrix());
  EXPECT_EQ(at.interpolate(5).matrix(), b.matrix());
  EXPECT_EQ(at.interpolate(-100).matrix(), a.matrix());
  EXPECT_EQ(at.interpolate(100).matrix(), b.matrix());
  // Just inside the interval the composition is continuous with the key.
  expectMatrixNear(at.interpolate(nextFloatUp(2.f)).matrix(), a.matrix(), 1e-4);
  expectMatrixNear(at.interpolate(nextFloatDown(5.f)).matrix(), b.matrix(), 1e-4);
}

TEST(AnimatedTransform, EqualKeysAreNotAnimated) {
  Transform t = translate(Vector3f(1, 2, 3)) * rotateX(20);
  AnimatedTransform at(t, 0, t, 1);
  EXPECT_FALSE(at.isAnimated());
  EXPECT_EQ(at.interpolate(0.5f).matrix(), t.matrix());
}

TEST(AnimatedTransform, RotationHalfWayIsHalfTheAngle) {
  AnimatedTransform at(Transform(), 0, rotateZ(90), 1);
  expectMatrixNear(at.interpolate(0.5f).matrix(), rotateZ(45).matrix(), 1e-6);
  // Slerp turns at a constant rate: a quarter of the time is a quarter of the angle.
  expectMatrixNear(at.interpolate(0.25f).matrix(), rotateZ(22.5f).matrix(), 1e-6);
  // A rotation keeps lengths half way, where a matrix lerp would shrink by cos 45.
  Vector3f v = at.interpolate(0.5f)(Vector3f(1, 0, 0));
  EXPECT_NEAR(v.length(), 1, 1e-6);
}

TEST(AnimatedTransform, ShorterArcIsTaken) {
  // 270 degrees one way is 90 the other.
  AnimatedTransform at(Transform(), 0, rotateZ(270), 1);
  expectMatrixNear(at.interpolate(0.5f).matrix(), rotateZ(-45).matrix(), 1e-6);
}

TEST(AnimatedTransform, TranslationAndScaleAreLinear) {
  AnimatedTransform at(translate(Vector3f(0, 0, 0)) * scale(1, 1, 1), 0,
                       translate(Vector3f(4, -8, 2)) * scale(3, 5, 1), 2);
  expectMatrixNear(at.interpolate(0.5f).matrix(),
                   (translate(Vector3f(1, -2, 0.5f)) * scale(1.5f, 2, 1)).matrix(), 1e-6);
}

TEST(AnimatedTransform, MirroredKeysStayMirrored) {
  Transform d = scale(-1, 1, 1);
  AnimatedTransform at(d, 0, d * rotateZ(90), 1);
  Transform mid = at.interpolate(0.5f);
  expectMatrixNear(mid.matrix(), (d * rotateZ(45)).matrix(), 1e-6);
  EXPECT_TRUE(mid.swapsHandedness());
}

TEST(AnimatedTransform, InterpolatedInverseIsInverse) {
  RNG rng(3);
  AnimatedTransform at(randomAffine(rng, false), 0, randomAffine(rng, false), 1);
  for (Float t : {0.1f, 0.37f, 0.5f, 0.93f}) {
    Transform x = at.interpolate(t);
    Matrix4x4 p = mul(x.matrix(), x.inverseMatrix());
    expectMatrixNear(p, Matrix4x4(), 1e-4);
  }
}

// The box at 1000 random times (and at the end points) lies inside motionBounds; and the
// bounds are not much bigger than the union over 20000 times.
void checkMotionBounds(const AnimatedTransform& at, const Bounds3f& box, uint64_t seed) {
  Bounds3f mb = at.motionBounds(box);
  RNG rng(seed);
  Bounds3f swept;
  for (int k = 0; k < 1000; ++k) {
    Float t = lerp(rng.uniformFloat(), at.startTime(), at.endTime());
    Bounds3f b = at.interpolate(t)(box);
    swept = unionOf(swept, b);
    for (int c = 0; c < 8; ++c)
      ASSERT_TRUE(mb.inside(b.corner(c))) << "t = " << t << " corner " << c;
  }
  for (Float t : {at.startTime(), at.endTime()}) {
    Bounds3f b = at.interpolate(t)(box);
    for (int c = 0; c < 8; ++c) ASSERT_TRUE(mb.inside(b.corner(c)));
  }
  for (int k = 0; k <= 20000; ++k)
    swept = unionOf(swept, at.interpolate(lerp(k / 20000.f, at.startTime(), at.endTime()))(box));
  // Allowed slack: 0.1% of the sweep, plus the rounding pad of some thirty ulps of the largest
  // coordinate (motionBounds' 2e-6 relative on each side).
  Vector3f slack = (mb.diagonal() - swept.diagonal());
  Float size = maxComponent(swept.diagonal());
  Float magnitude =
      std::max(maxComponent(abs(Vector3f(mb.pMin))), maxComponent(abs(Vector3f(mb.pMax))));
  EXPECT_LT(maxComponent(slack), 1e-3f * size + 4e-6f * magnitude)
      << "motion bounds much looser than the sweep";
}

TEST(AnimatedTransform, MotionBoundsContainTheMovingBox) {
  Bounds3f box(Point3f(-1, -0.5f, -2), Point3f(2, 1, 0.5f));
  checkMotionBounds(AnimatedTransform(Transform(), 0, rotateZ(90), 1), box, 1);
  checkMotionBounds(AnimatedTransform(translate(Vector3f(3, 0, 0)), 0,
                                      translate(Vector3f(3, 0, 0)) * rotateZ(170), 1),
                    box, 2);
  checkMotionBounds(
      AnimatedTransform(
          translate(Vector3f(-5, 1, 2)) * scale(1, 2, 1), 1,
          translate(Vector3f(5, 3, -2)) * rotate(120, Vector3f(1, 1, 1)) * scale(3, 0.5f, 2), 3),
      box, 3);
  checkMotionBounds(AnimatedTransform(translate(Vector3f(1e4f, 1e4f, 1e4f)), 0,
                                      translate(Vector3f(1e4f + 1, 1e4f, 1e4f)) * rotateX(60), 1),
                    box, 4);
  RNG rng(5);
  for (int k = 0; k < 10; ++k) {
    AnimatedTransform at(randomAffine(rng, k % 3 == 0), 0, randomAffine(rng, k % 3 == 0), 1);
    checkMotionBounds(at, box, 10 + k);
  }
}

TEST(AnimatedTransform, PureTranslationBoundsAreTheTwoEnds) {
  Bounds3f box(Point3f(0, 0, 0), Point3f(1, 1, 1));
  AnimatedTransform at(Transform(), 0, translate(Vector3f(10, 0, 0)), 1);
  Bounds3f mb = at.motionBounds(box);
  EXPECT_NEAR(mb.pMin.x, 0, 1e-4);
  EXPECT_NEAR(mb.pMax.x, 11, 1e-4);
  EXPECT_NEAR(mb.pMax.y, 1, 1e-4);
}

}  // namespace
}  // namespace candela
