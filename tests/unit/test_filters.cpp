// Pixel filters: integrals against their closed forms, importance-sampled offsets against |f| by
// chi-square, weights (constant for the box, mean = integral for all), constant radiance staying
// constant through the film, and the factory's names, defaults and errors.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "core/rng.h"
#include "film/film.h"
#include "filters/box_filter.h"
#include "filters/filter.h"
#include "filters/gaussian_filter.h"
#include "filters/mitchell_filter.h"
#include "filters/sinc_filter.h"
#include "filters/triangle_filter.h"
#include "samplers/random_sampler.h"
#include "samplers/sampler.h"
#include "support/param_items.h"
#include "support/tail_probabilities.h"

namespace candela {
namespace {

// Integral of the shifted Gaussian e^{-a x^2} - e^{-a r^2} over [-r, r].
double gaussianIntegral1D(double r, double a) {
  return std::sqrt(M_PI / a) * std::erf(std::sqrt(a) * r) - 2 * r * std::exp(-a * r * r);
}

// Pearson's chi-square of observed against expected counts, bins with expected < 5 pooled;
// returns the p-value.
double chiSquarePValue(const std::vector<double>& observed, const std::vector<double>& expected) {
  double chi2 = 0, pooledObs = 0, pooledExp = 0;
  int bins = 0;
  for (size_t i = 0; i < observed.size(); ++i) {
    if (expected[i] < 5) {
      pooledObs += observed[i];
      pooledExp += expected[i];
      continue;
    }
    chi2 += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
    ++bins;
  }
  if (pooledExp > 0) {
    chi2 += (pooledObs - pooledExp) * (pooledObs - pooledExp) / pooledExp;
    ++bins;
  }
  return stats::chiSquareSurvival(chi2, bins - 1);
}

struct NamedFilter {
  std::string name;
  std::unique_ptr<Filter> filter;
};

std::vector<NamedFilter> allFilters() {
  std::vector<NamedFilter> v;
  v.push_back({"box", std::make_unique<BoxFilter>(Vector2f(0.5f, 0.5f))});
  v.push_back({"box wide", std::make_unique<BoxFilter>(Vector2f(1.5f, 0.75f))});
  v.push_back({"gaussian", std::make_unique<GaussianFilter>(Vector2f(2, 2), 2.f)});
  v.push_back({"gaussian narrow", std::make_unique<GaussianFilter>(Vector2f(1.5f, 1), 1.f)});
  v.push_back({"mitchell", std::make_unique<MitchellFilter>(Vector2f(2, 2), 1.f / 3, 1.f / 3)});
  v.push_back({"catmull-rom", std::make_unique<MitchellFilter>(Vector2f(2, 1.25f), 0.f, 0.5f)});
  v.push_back({"triangle", std::make_unique<TriangleFilter>(Vector2f(2, 2))});
  v.push_back({"triangle narrow", std::make_unique<TriangleFilter>(Vector2f(0.75f, 1.5f))});
  v.push_back({"sinc", std::make_unique<LanczosSincFilter>(Vector2f(4, 4), 3.f)});
  v.push_back({"sinc 2 lobes", std::make_unique<LanczosSincFilter>(Vector2f(2, 3), 2.f)});
  return v;
}

TEST(Filter, BoxIntegralIsArea) {
  EXPECT_FLOAT_EQ(BoxFilter(Vector2f(0.5f, 0.5f)).integral(), 1.f);
  EXPECT_FLOAT_EQ(BoxFilter(Vector2f(1.5f, 0.75f)).integral(), 4 * 1.5f * 0.75f);
}

TEST(Filter, GaussianIntegralMatchesErfForm) {
  struct Case {
    Float rx, ry, alpha;
  };
  for (Case c : {Case{2, 2, 2}, Case{1.5f, 1, 1}, Case{0.5f, 3, 4}}) {
    GaussianFilter f(Vector2f(c.rx, c.ry), c.alpha);
    double exact = gaussianIntegral1D(c.rx, c.alpha) * gaussianIntegral1D(c.ry, c.alpha);
    EXPECT_NEAR(f.integral(), exact, 1e-3 * exact) << c.rx << " " << c.ry << " " << c.alpha;
  }
}

TEST(Filter, MitchellIntegralIsQuarterOfWidths) {
  // The cubic integrates to 1 over [-2, 2] for every B and C (its pieces give (3 - B/4 + C/2)/6
  // and (B/4 - C/2)/6 per side); stretched onto [-r, r] that is r/2 per axis.
  struct Case {
    Float rx, ry, b, c;
  };
  for (Case c : {Case{2, 2, 1.f / 3, 1.f / 3}, Case{2, 1, 0, 0.5f}, Case{3, 1.5f, 1, 0}}) {
    MitchellFilter f(Vector2f(c.rx, c.ry), c.b, c.c);
    double exact = (c.rx / 2.0) * (c.ry / 2.0);
    EXPECT_NEAR(f.integral(), exact, 1e-4 * exact) << c.rx << " " << c.ry << " B " << c.b;
  }
}

TEST(Filter, TriangleIntegralIsSquaredWidths) {
  // Per axis the tent max(0, r - |x|) over [-r, r] is a triangle of base 2r and height r: r^2.
  // The table's midpoint rule is exact for it (linear on every cell, the kink on a cell edge).
  for (Vector2f r : {Vector2f(2, 2), Vector2f(0.75f, 1.5f), Vector2f(0.5f, 3)}) {
    TriangleFilter f(r);
    double exact = double(r.x) * r.x * double(r.y) * r.y;
    EXPECT_NEAR(f.integral(), exact, 1e-5 * exact) << r.x << " " << r.y;
  }
  TriangleFilter f(Vector2f(2, 1));
  EXPECT_FLOAT_EQ(f.evaluate(Point2f(0, 0)), 2.f);
  EXPECT_FLOAT_EQ(f.evaluate(Point2f(1, 0.5f)), 0.5f);
  EXPECT_EQ(f.evaluate(Point2f(2, 0)), 0.f);
  EXPECT_EQ(f.evaluate(Point2f(0.5f, -1)), 0.f);
}

// The 1D Lanczos-windowed sinc on [-r, r] in double precision, by composite Simpson on 20000
// intervals (error far below 1e-9 for this smooth integrand).
double sincIntegral1D(double r, double tau) {
  auto f = [&](double x) {
    double t = std::abs(x / r);
    if (t < 1e-12) return 1.0;
    double a = M_PI * t;
    return std::sin(a * tau) / (a * tau) * std::sin(a) / a;
  };
  const int n = 20000;
  double h = 2 * r / n, sum = f(-r) + f(r);
  for (int i = 1; i < n; ++i) sum += f(-r + i * h) * (i % 2 ? 4 : 2);
  return sum * h / 3;
}

TEST(Filter, SincIntegralMatchesQuadrature) {
  struct Case {
    Float rx, ry, tau;
  };
  for (Case c : {Case{4, 4, 3}, Case{2, 3, 2}, Case{1.5f, 4, 4}}) {
    LanczosSincFilter f(Vector2f(c.rx, c.ry), c.tau);
    double exact = sincIntegral1D(c.rx, c.tau) * sincIntegral1D(c.ry, c.tau);
    EXPECT_NEAR(f.integral(), exact, 1e-4 * exact) << c.rx << " " << c.ry << " " << c.tau;
  }
}

TEST(Filter, SincValues) {
  LanczosSincFilter f(Vector2f(4, 4), 3);
  EXPECT_EQ(f.windowedSinc(0), 1.f);
  EXPECT_EQ(f.evaluate(Point2f(0, 0)), 1.f);
  EXPECT_EQ(f.windowedSinc(9e-6f), 1.f);  // below 1e-5 it is taken as 1
  // Zeros where tau x' is a nonzero integer, and at and beyond the radius.
  for (Float x : {1.f / 3, 2.f / 3, 1.f}) EXPECT_NEAR(f.windowedSinc(x), 0, 1e-6) << x;
  EXPECT_EQ(f.windowedSinc(1.01f), 0.f);
  EXPECT_EQ(f.evaluate(Point2f(4.5f, 0)), 0.f);
  // The first negative lobe, and a value in closed form: x' = 1/2 gives
  // sin(3 pi/2)/(3 pi/2) * sin(pi/2)/(pi/2) = -4 / (3 pi^2).
  EXPECT_LT(f.windowedSinc(0.5f), 0.f);
  EXPECT_NEAR(f.windowedSinc(0.5f), -4 / (3 * M_PI * M_PI), 1e-6);
  EXPECT_NEAR(f.evaluate(Point2f(2, -2)), 16 / (9 * M_PI * M_PI * M_PI * M_PI), 1e-6);
  // Even in x and y.
  EXPECT_EQ(f.evaluate(Point2f(-1.3f, 0.7f)), f.evaluate(Point2f(1.3f, -0.7f)));
}

TEST(Filter, ZeroAtTheEdgeAndOneAtCentreWhereDefined) {
  GaussianFilter g(Vector2f(2, 2), 2);
  EXPECT_EQ(g.evaluate(Point2f(2, 0)), 0.f);
  EXPECT_EQ(g.evaluate(Point2f(0, -2)), 0.f);
  MitchellFilter m(Vector2f(2, 2), 1.f / 3, 1.f / 3);
  EXPECT_NEAR(m.evaluate(Point2f(2, 0)), 0.f, 1e-7);
  // Mitchell at 0 is (6 - 2B)/6 per axis.
  Float m0 = (6 - 2.f / 3) / 6;
  EXPECT_NEAR(m.evaluate(Point2f(0, 0)), m0 * m0, 1e-6);
  // The negative lobe: between 1 and 2 of the cubic's units, i.e. |x| in (1, 2) for radius 2.
  EXPECT_LT(m.evaluate(Point2f(1.5f, 0)), 0.f);
  EXPECT_EQ(BoxFilter(Vector2f(0.5f, 0.5f)).evaluate(Point2f(0.49f, -0.5f)), 1.f);
}

TEST(Filter, TableIsAtLeast64CellsPerAxis) {
  BoxFilter box(Vector2f(0.5f, 0.5f));
  EXPECT_GE(box.tableWidth(), 64);
  EXPECT_GE(box.tableHeight(), 64);
  GaussianFilter g(Vector2f(4, 2), 2);
  EXPECT_GE(g.tableWidth(), 32 * 4);
}

TEST(Filter, BoxWeightIsExactlyConstant) {
  for (Vector2f r : {Vector2f(0.5f, 0.5f), Vector2f(1.5f, 0.75f), Vector2f(0.3f, 2.2f)}) {
    BoxFilter box(r);
    RNG rng(7);
    Float first = box.sample(Point2f(0.5f, 0.5f)).weight;
    EXPECT_NEAR(first, 4 * r.x * r.y, 1e-5 * 4 * r.x * r.y);
    for (int i = 0; i < 20000; ++i) {
      Point2f u(rng.uniformFloat(), rng.uniformFloat());
      FilterSample s = box.sample(u);
      ASSERT_EQ(s.weight, first) << "u " << u.x << " " << u.y;
      ASSERT_LE(std::abs(s.p.x), r.x);
      ASSERT_LE(std::abs(s.p.y), r.y);
    }
    // The corners of [0,1)^2 reach the corners of the support.
    EXPECT_EQ(box.sample(Point2f(0, 0)).p.x, -r.x);
    EXPECT_NEAR(box.sample(Point2f(kOneMinusEpsilon, kOneMinusEpsilon)).p.y, r.y, 1e-5);
  }
}

TEST(Filter, MeanWeightIsTheIntegral) {
  // E[f/pdf] = integral of f: the sample mean of the weights within 4 standard errors of it.
  const int n = 200000;
  for (const auto& [name, f] : allFilters()) {
    RNG rng(11, 22);
    double sum = 0, sumSq = 0;
    for (int i = 0; i < n; ++i) {
      double w = f->sample(Point2f(rng.uniformFloat(), rng.uniformFloat())).weight;
      sum += w;
      sumSq += w * w;
    }
    double mean = sum / n, stdErr = std::sqrt(std::max(0.0, sumSq / n - mean * mean) / n);
    EXPECT_NEAR(mean, f->integral(), 4 * stdErr + 1e-6 * std::abs(mean)) << name;
  }
}

TEST(Filter, SampledOffsetsFollowAbsoluteFilterChiSquare) {
  const int kBins = 16, kSamples = 200000, kSub = 24;
  for (const auto& [name, f] : allFilters()) {
    Vector2f r = f->radius();
    std::vector<double> observed(kBins * kBins, 0), expected(kBins * kBins, 0);
    RNG rng(0x5eed, 1234);
    for (int i = 0; i < kSamples; ++i) {
      FilterSample s = f->sample(Point2f(rng.uniformFloat(), rng.uniformFloat()));
      int bx = clamp(int((s.p.x + r.x) / (2 * r.x) * kBins), 0, kBins - 1);
      int by = clamp(int((s.p.y + r.y) / (2 * r.y) * kBins), 0, kBins - 1);
      observed[by * kBins + bx] += 1;
    }
    // Expected counts from |f| itself on a finer midpoint grid than the sampler's table.
    double total = 0;
    double h = 1.0 / (kBins * kSub);
    for (int by = 0; by < kBins; ++by)
      for (int bx = 0; bx < kBins; ++bx) {
        double sum = 0;
        for (int sy = 0; sy < kSub; ++sy)
          for (int sx = 0; sx < kSub; ++sx) {
            double ux = (bx * kSub + sx + 0.5) * h, uy = (by * kSub + sy + 0.5) * h;
            Point2f p(Float(-r.x + 2 * r.x * ux), Float(-r.y + 2 * r.y * uy));
            sum += std::abs(f->evaluate(p));
          }
        expected[by * kBins + bx] = sum;
        total += sum;
      }
    for (double& e : expected) e *= kSamples / total;
    double p = chiSquarePValue(observed, expected);
    EXPECT_GT(p, 0.01) << name;
  }
}

TEST(Filter, ConstantRadianceStaysConstantThroughTheFilm) {
  const Spectrum L(0.25f, 1.5f, 3.f);
  for (auto& nf : allFilters()) {
    std::string name = nf.name;
    Film film(Point2i(8, 6), Bounds2f(Point2f(0, 0), Point2f(1, 1)), std::move(nf.filter),
              "unused.exr");
    RandomSampler sampler(16, 99);
    for (int y = 0; y < 6; ++y)
      for (int x = 0; x < 8; ++x)
        for (int i = 0; i < sampler.samplesPerPixel(); ++i) {
          Point2i pixel(x, y);
          sampler.startPixelSample(pixel, i);
          CameraSample cs = getCameraSample(sampler, pixel, film.filter());
          film.addSample(pixel, L, 1, cs.filterWeight);
        }
    for (int y = 0; y < 6; ++y)
      for (int x = 0; x < 8; ++x) {
        Spectrum v = film.pixelValue(Point2i(x, y));
        for (int c = 0; c < 3; ++c) ASSERT_NEAR(v[c], L[c], 1e-5 * L[c]) << name;
        ASSERT_NEAR(film.pixelAlpha(Point2i(x, y)), 1, 1e-5) << name;
      }
  }
}

TEST(FilterFactory, DefaultsFollowPbrtV2) {
  FileLoc loc{"scene.pbrt", 1, 1};
  ParamSet none;
  auto box = createFilter("box", none, loc);
  EXPECT_EQ(box->radius().x, 0.5f);
  EXPECT_EQ(box->radius().y, 0.5f);
  auto gauss = createFilter("gaussian", none, loc);
  ASSERT_NE(dynamic_cast<GaussianFilter*>(gauss.get()), nullptr);
  EXPECT_EQ(gauss->radius().x, 2.f);
  EXPECT_EQ(dynamic_cast<GaussianFilter*>(gauss.get())->alpha(), 2.f);
  auto mitchell = createFilter("mitchell", none, loc);
  auto* m = dynamic_cast<MitchellFilter*>(mitchell.get());
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(mitchell->radius().y, 2.f);
  EXPECT_FLOAT_EQ(m->b(), 1.f / 3);
  EXPECT_FLOAT_EQ(m->c(), 1.f / 3);
}

TEST(FilterFactory, TriangleAndSincDefaults) {
  FileLoc loc{"scene.pbrt", 1, 1};
  auto tri = createFilter("triangle", ParamSet(), loc);
  ASSERT_NE(dynamic_cast<TriangleFilter*>(tri.get()), nullptr);
  EXPECT_EQ(tri->radius().x, 2.f);
  EXPECT_EQ(tri->radius().y, 2.f);
  auto sinc = createFilter("sinc", ParamSet(), loc);
  auto* s = dynamic_cast<LanczosSincFilter*>(sinc.get());
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(sinc->radius().x, 4.f);
  EXPECT_EQ(sinc->radius().y, 4.f);
  EXPECT_EQ(s->tau(), 3.f);
  ParamSet ps;
  ps.add(test::floats("tau", {2}));
  ps.add(test::floats("ywidth", {1.5f}));
  sinc = createFilter("sinc", ps, loc);
  EXPECT_EQ(dynamic_cast<LanczosSincFilter&>(*sinc).tau(), 2.f);
  EXPECT_EQ(sinc->radius().y, 1.5f);
  ParamSet bad;
  bad.add(test::floats("tau", {0}));
  EXPECT_THROW(createFilter("sinc", bad, loc), SceneError);
}

TEST(FilterFactory, ReadsParameters) {
  ParamSet ps;
  ps.add(test::floats("xwidth", {1.25f}));
  ps.add(test::floats("ywidth", {0.75f}));
  ps.add(test::floats("B", {0}));
  ps.add(test::floats("C", {0.5f}));
  auto f = createFilter("mitchell", ps, FileLoc{});
  EXPECT_EQ(f->radius().x, 1.25f);
  EXPECT_EQ(f->radius().y, 0.75f);
  EXPECT_EQ(dynamic_cast<MitchellFilter&>(*f).c(), 0.5f);
  int unused = 0;
  ps.forEachUnused([&](const ParamItem&) { ++unused; });
  EXPECT_EQ(unused, 0);
}

TEST(FilterFactory, UnknownNameListsKnownFilters) {
  try {
    createFilter("lanczos", ParamSet(), FileLoc{"a.pbrt", 4, 2});
    FAIL() << "no error";
  } catch (const SceneError& e) {
    std::string what = e.what();
    EXPECT_NE(what.find("a.pbrt:4:2"), std::string::npos) << what;
    EXPECT_NE(what.find("lanczos"), std::string::npos) << what;
    for (const char* known : {"box", "gaussian", "mitchell", "triangle", "sinc"})
      EXPECT_NE(what.find(known), std::string::npos) << what;
  }
}

TEST(FilterFactory, NonPositiveWidthIsAnErrorAtTheParameter) {
  ParamSet ps;
  ps.add(test::floats("xwidth", {0}, FileLoc{"filters.pbrt", 3, 7}));
  try {
    createFilter("gaussian", ps, FileLoc{"b.pbrt", 1, 1});
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.location().line, 3) << e.what();
    EXPECT_NE(std::string(e.what()).find("xwidth"), std::string::npos);
  }
}

}  // namespace
}  // namespace candela
