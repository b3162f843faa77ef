// Quadric area and sampling: areas against numerical integration of the model's area element,
// samples on the surface and uniform by area (chi-square, fixed seed, significance 0.001), and
// the solid-angle density pdf(ref, wi) against sample(ref, u) and against the visible fraction of
// the area.
#include <gtest/gtest.h>

#include "core/rng.h"
#include "core/sampling.h"
#include "quadric_models.h"

namespace candela {
namespace {

using test::D3;
using test::QuadricModel;

const Transform& similarity() {
  static const Transform t = translate(Vector3f(-1, 4, 2)) * rotate(-63, Vector3f(0.3f, 1, -0.2f)) *
                             scale(1.7f, 1.7f, 1.7f);
  return t;
}
constexpr double kSimilarityScale = 1.7;

Point2f next2D(RNG& rng) {
  Float u0 = rng.uniformFloat();
  return Point2f(u0, rng.uniformFloat());
}

TEST(QuadricSampling, AreaMatchesIntegratedAreaElement) {
  for (const QuadricModel& m : test::allModels()) {
    double expected = m.area(0, 1, 0, 1, 400);
    EXPECT_NEAR(m.make(Transform(), false)->area(), expected, 1e-5 * expected) << m.name;
    // A similarity scales areas by the square of its scale.
    EXPECT_NEAR(m.make(similarity(), false)->area(), expected * kSimilarityScale * kSimilarityScale,
                1e-5 * expected * kSimilarityScale * kSimilarityScale)
        << m.name;
  }
  // The disk's area is exact under any affine map: here x 2, y 3 and a shear out of its plane.
  Transform affine = Transform(Matrix4x4(2, 0, 0, 0, 0, 3, 0, 0, 0.5f, 0.25f, 1, 0, 0, 0, 0, 1));
  DiskShape disk(affine, false, 0.5f, 1, 0.5f, 360);
  // The images of the x and y axes are (2, 0, 0.5) and (0, 3, 0.25): |cross| = sqrt(2.25 + .25 +
  // 36) ... computed exactly below.
  Float crossLen = cross(Vector3f(2, 0, 0.5f), Vector3f(0, 3, 0.25f)).length();
  EXPECT_NEAR(disk.area(), kPi * 0.75f * crossLen, 1e-5 * disk.area());
}

TEST(QuadricSampling, SamplesLieOnTheSurface) {
  RNG rng(21);
  for (const QuadricModel& m : test::allModels()) {
    std::unique_ptr<Quadric> s = m.make(similarity(), false);
    for (int i = 0; i < 2000; ++i) {
      Float pdf;
      Interaction it = s->sample(next2D(rng), &pdf);
      EXPECT_NEAR(pdf, 1 / s->area(), 1e-6f / s->area());
      D3 q = test::toObject(similarity(), it.p);
      Point2f uv = m.uvOf(q);
      EXPECT_GE(uv.x, -1e-5f) << m.name;
      EXPECT_LE(uv.x, 1 + 1e-5f) << m.name;
      EXPECT_GE(uv.y, -1e-5f) << m.name;
      EXPECT_LE(uv.y, 1 + 1e-5f) << m.name;
      D3 back = m.P(uv.x, uv.y);
      EXPECT_LT(test::lenD(test::sub(back, q)), 2e-5 * m.size)
          << m.name << " uv " << uv.x << ", " << uv.y;
      // The world point is within its error bound of the exact image of q (float rounding of the
      // sample is far below the bound's gamma(2) |p|).
      EXPECT_FALSE(it.pError.hasNaN());
      EXPECT_GT(it.pError.x, 0);
      EXPECT_LT(it.pError.x, 1e-5f * (std::abs(it.p.x) + 10));
    }
  }
}

// Pearson's chi-square of the samples' (u, v) in an 8 x 8 histogram against the model's area of
// each cell: uniform by area.
TEST(QuadricSampling, UniformByAreaChiSquare) {
  const int n = 8, count = 100000;
  RNG rng(22);
  for (const QuadricModel& m : test::allModels()) {
    std::unique_ptr<Quadric> s = m.make(similarity(), false);
    std::vector<double> observed(n * n, 0), expected(n * n);
    double total = m.area(0, 1, 0, 1, 256);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        expected[i * n + j] =
            count * m.area(double(i) / n, double(i + 1) / n, double(j) / n, double(j + 1) / n, 32) /
            total;
    for (int k = 0; k < count; ++k) {
      Float pdf;
      Interaction it = s->sample(next2D(rng), &pdf);
      Point2f uv = m.uvOf(test::toObject(similarity(), it.p));
      int i = clamp(int(uv.x * n), 0, n - 1), j = clamp(int(uv.y * n), 0, n - 1);
      observed[i * n + j] += 1;
    }
    double chi2 = 0;
    for (int c = 0; c < n * n; ++c)
      chi2 += (observed[c] - expected[c]) * (observed[c] - expected[c]) / expected[c];
    double p = test::chiSquarePValue(chi2, n * n - 1);
    EXPECT_GT(p, 1e-3) << m.name << " chi2 " << chi2;
  }
}

// ref points around and inside each shape: outside at 2.5 sizes, and on the axis.
std::vector<Point3f> refPoints(const QuadricModel& m) {
  D3 axis = {0, 0, 0.5 * (m.P(0.5, 0)[2] + m.P(0.5, 1)[2]) + (m.flat ? 0.5 * m.size : 0)};
  std::vector<D3> obj = {{2.5 * m.size, 0.7 * m.size, 0.9 * m.size}, axis};
  std::vector<Point3f> w;
  for (const D3& p : obj) w.push_back(similarity()(Point3f(Float(p[0]), Float(p[1]), Float(p[2]))));
  return w;
}

TEST(QuadricSampling, SolidAnglePdfMatchesSample) {
  RNG rng(23);
  for (const QuadricModel& m : test::allModels()) {
    std::unique_ptr<Quadric> s = m.make(similarity(), false);
    for (const Point3f& p : refPoints(m)) {
      Interaction ref(p, 0);
      int checked = 0;
      for (int i = 0; i < 2000; ++i) {
        Float pdf;
        Interaction it = s->sample(ref, next2D(rng), &pdf);
        Vector3f wi = normalize(it.p - ref.p);
        // Only where the sample is the first surface point in its direction does pdf(ref, wi),
        // which finds that first point, describe it.
        Float t;
        if (s->intersect(Ray(ref.p, it.p - ref.p, 1 - 1e-3f), &t, nullptr)) continue;
        // Near grazing the density is ill-conditioned: the float ray toward the sample meets
        // the surface up to (position rounding) / cos away, where the normal differs.
        if (pdf == 0 || absDot(it.n, wi) < 0.05f) continue;
        ++checked;
        EXPECT_NEAR(s->pdf(ref, wi), pdf, 2e-3f * pdf) << m.name;
      }
      EXPECT_GT(checked, 300) << m.name;
    }
  }
}

// The integral of pdf(ref, w) over all directions is the fraction of the area visible from ref
// (pdf counts the first surface point along w only). Both sides by Monte Carlo with fixed seeds;
// they must agree within 4.5 combined standard errors (two-sided significance ~1e-5).
TEST(QuadricSampling, PdfIntegratesToVisibleFraction) {
  RNG rng(24);
  for (const QuadricModel& m : test::allModels()) {
    std::unique_ptr<Quadric> s = m.make(similarity(), false);
    Point3f centre;
    Float radius;
    s->worldBound().boundingSphere(&centre, &radius);
    for (const Point3f& p : refPoints(m)) {
      Interaction ref(p, 0);
      // Directions uniform in the cone around the bounding sphere (the whole sphere of
      // directions from inside it).
      Float dc = distance(p, centre);
      Float cosMax = dc > radius ? std::sqrt(1 - radius * radius / (dc * dc)) : -1;
      Vector3f axis = dc > 0 ? (centre - p) / dc : Vector3f(0, 0, 1), x, y;
      coordinateSystem(axis, &x, &y);
      const int nDir = 200000;
      double sum = 0, sum2 = 0;
      for (int i = 0; i < nDir; ++i) {
        Vector3f l = sampleUniformCone(next2D(rng), cosMax);
        Vector3f w = x * l.x + y * l.y + axis * l.z;
        double f = s->pdf(ref, w) / uniformConePdf(cosMax);
        sum += f;
        sum2 += f * f;
      }
      double integral = sum / nDir, varI = (sum2 / nDir - integral * integral) / nDir;
      // The visible fraction: area samples with nothing in front of them.
      const int nArea = 40000;
      int visible = 0;
      // And a second estimate of the integral with bounded variance: directions toward area
      // samples have the density sum_k d_k^2 / (cos_k A) over all the surface points x_k along
      // them (found by continuing past each hit), of which pdf(ref, w) must be the first term.
      double sumW = 0, sumW2 = 0;
      for (int i = 0; i < nArea; ++i) {
        Float pdf, t;
        Interaction it = s->sample(next2D(rng), &pdf);
        if (!s->intersect(Ray(p, it.p - p, 1 - 1e-4f), &t, nullptr)) ++visible;
        Vector3f w = normalize(it.p - p);
        double density = 0;
        Ray r(p, w);
        SurfaceInteraction si;
        for (int k = 0; k < 4 && s->intersect(r, &t, &si); ++k) {
          Float cosK = absDot(si.n, w);
          if (cosK > 0) density += distanceSquared(p, si.p) / (cosK * s->area());
          r = si.spawnRay(w);
        }
        double wgt = density > 0 ? s->pdf(ref, w) / density : 0;
        sumW += wgt;
        sumW2 += wgt * wgt;
      }
      double fraction = double(visible) / nArea;
      double varF = fraction * (1 - fraction) / nArea;
      double sigma = std::sqrt(varI + varF);
      EXPECT_NEAR(integral, fraction, 4.5 * sigma + 1e-9)
          << m.name << " from " << p << ": sigma " << sigma;
      // Directions sampled by uniform cones make pdf's 1/cos at silhouettes a heavy tail; this
      // only asks for a useful test.
      EXPECT_LT(sigma, 0.05) << m.name;
      double meanW = sumW / nArea, varW = (sumW2 / nArea - meanW * meanW) / nArea;
      double sigmaW = std::sqrt(varW + varF);
      EXPECT_NEAR(meanW, fraction, 4.5 * sigmaW + 1e-9)
          << m.name << " from " << p << ": sigma " << sigmaW;
    }
  }
}

}  // namespace
}  // namespace candela
