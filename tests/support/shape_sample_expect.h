// Test helper: Shape::sampleFrom against Shape::sample(ref, ...) for one reference point and u.
#pragma once

#include <gtest/gtest.h>

#include "shapes/shape.h"

namespace candela::test {

// Expects sampleFrom's point, normal, error bound and density to be sample(ref, ...)'s and, when
// the density is not 0, its direction to be normalize(p - ref.p) bit for bit. Returns whether a
// direction was compared.
inline bool expectSampleFromIsSample(const Shape& shape, const Interaction& ref, const Point2f& u) {
  Float pdf = -1, pdfFrom = -1;
  Vector3f wi(7, 7, 7);
  Interaction it = shape.sample(ref, u, &pdf);
  Interaction from = shape.sampleFrom(ref, u, &pdfFrom, &wi);
  EXPECT_EQ(it.p, from.p);
  EXPECT_EQ(it.n, from.n);
  EXPECT_EQ(it.pError, from.pError);
  EXPECT_EQ(pdf, pdfFrom);
  if (pdfFrom == 0) return false;
  EXPECT_EQ(wi, normalize(from.p - ref.p));
  return true;
}

}  // namespace candela::test
