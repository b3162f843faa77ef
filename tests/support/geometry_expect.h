// Test helpers: componentwise comparison of vectors and points, a camera sample at a film
// position, and whether a camera's rays there depend on the lens sample.
#pragma once

#include <gtest/gtest.h>

#include "cameras/camera.h"
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

// Whether the camera's rays through film position (x, y) are the same bits for two lens samples
// far apart (what the renderer relies on when readsLensSample() is false).
inline bool rayIgnoresLensSample(const Camera& camera, Float x, Float y) {
  Ray a, b;
  camera.generateRay(cameraSample(x, y, Point2f(0, 0)), &a);
  camera.generateRay(cameraSample(x, y, Point2f(0.9f, 0.3f)), &b);
  return a.o == b.o && a.d == b.d;
}

}  // namespace candela::test
