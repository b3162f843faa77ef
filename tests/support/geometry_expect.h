// Test helpers: componentwise comparison of vectors and points, and a camera sample at a film
// position.
#pragma once

#include <gtest/gtest.h>

#include "samplers/sampler.h"

namespace candela::test {

inline void expectNear(const Vector3f& a, const Vector3f& b, Float tol, const char* what = "") {
  EXPECT_NEAR(a.x, b.x, tol) << what << " " << a << " vs " << b;
  EXPECT_NEAR(a.y, b.y, tol) << what << " " << a << " vs " << b;
  EXPECT_NEAR(a.z, b.z, tol) << what << " " << a << " vs " << b;
}
inline void expectNear(const Point3f& a, const Point3f& b, Float tol, const char* what = "") {
  expectNear(Vector3f(a), Vector3f(b), tol, what);
}

// pFilm = (x, y), the lens centre unless given, at time `time` of the shutter.
inline CameraSample cameraSample(Float x, Float y, Point2f lens = Point2f(0.5f, 0.5f),
                                 Float time = 0) {
  CameraSample s;
  s.pFilm = Point2f(x, y);
  s.pLens = lens;
  s.time = time;
  return s;
}

}  // namespace candela::test
