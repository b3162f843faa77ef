// Statistics for testing direction samplers against their pdfs (pbrt-v4 / Mitsuba style):
// adaptive cubature over (theta, phi) cells, the chi-square and Poisson tail probabilities, and a
// goodness-of-fit test over a theta x phi histogram.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "core/rng.h"
#include "core/vector.h"
#include "support/tail_probabilities.h"

namespace candela::stats {

// ---- adaptive cubature ---------------------------------------------------------------------

// Integrates f over [x0, x1] x [y0, y1] with 4 x 4 Gauss-Legendre rules: each rectangle's
// estimate is compared with the sum over its four quarters, which are refined until the two
// agree to max(absTol, relTol |I|); each quarter gets half the absolute tolerance (refinement
// concentrates along curves, where the number of rectangles doubles per level). minDepth forces a
// first subdivision so that a lobe narrower than a rectangle cannot slip between the nodes of every
// level.
class Cubature {
 public:
  Cubature(std::function<double(double, double)> f, double relTol, double absTol, int minDepth,
           int maxDepth)
      : f_(std::move(f)),
        relTol_(relTol),
        absTol_(absTol),
        minDepth_(minDepth),
        maxDepth_(maxDepth) {}
  double integrate(double x0, double x1, double y0, double y1) {
    return refine(x0, x1, y0, y1, rule(x0, x1, y0, y1), absTol_, 0);
  }
  int64_t evaluations() const { return evaluations_; }

 private:
  double rule(double x0, double x1, double y0, double y1) {
    static constexpr double node[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                                       0.8611363115940526};
    static constexpr double weight[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                                         0.3478548451374538};
    double cx = 0.5 * (x0 + x1), hx = 0.5 * (x1 - x0), cy = 0.5 * (y0 + y1), hy = 0.5 * (y1 - y0);
    double s = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        s += weight[i] * weight[j] * f_(cx + hx * node[i], cy + hy * node[j]);
    evaluations_ += 16;
    return s * hx * hy;
  }
  double refine(double x0, double x1, double y0, double y1, double whole, double absTol,
                int depth) {
    double xm = 0.5 * (x0 + x1), ym = 0.5 * (y0 + y1);
    double q[4] = {rule(x0, xm, y0, ym), rule(xm, x1, y0, ym), rule(x0, xm, ym, y1),
                   rule(xm, x1, ym, y1)};
    double parts = q[0] + q[1] + q[2] + q[3];
    if (depth >= maxDepth_ ||
        (depth >= minDepth_ &&
         std::abs(parts - whole) <= std::max(absTol, relTol_ * std::abs(parts))))
      return parts;
    return refine(x0, xm, y0, ym, q[0], absTol / 2, depth + 1) +
           refine(xm, x1, y0, ym, q[1], absTol / 2, depth + 1) +
           refine(x0, xm, ym, y1, q[2], absTol / 2, depth + 1) +
           refine(xm, x1, ym, y1, q[3], absTol / 2, depth + 1);
  }

  std::function<double(double, double)> f_;
  double relTol_, absTol_;
  int minDepth_, maxDepth_;
  int64_t evaluations_ = 0;
};

inline Vector3f directionFromAngles(double theta, double phi) {
  double s = std::sin(theta);
  return Vector3f(Float(s * std::cos(phi)), Float(s * std::sin(phi)), Float(std::cos(theta)));
}

// Integral over the sphere (or over theta in [theta0, theta1]) of a function of direction, on a
// nTheta x nPhi grid of cells each refined adaptively.
// The default tolerances (relative 1e-6, absolute 1e-8 per cell) give results of order 1 to
// ~1e-5.
inline double integrateSphere(const std::function<double(const Vector3f&)>& f, int nTheta = 20,
                              int nPhi = 40, double theta0 = 0, double theta1 = M_PI,
                              double relTol = 1e-6, double absTol = 1e-8) {
  Cubature c([&](double t, double p) { return f(directionFromAngles(t, p)) * std::sin(t); }, relTol,
             absTol, 2, 9);
  double sum = 0;
  for (int i = 0; i < nTheta; ++i)
    for (int j = 0; j < nPhi; ++j)
      sum += c.integrate(theta0 + (theta1 - theta0) * i / nTheta,
                         theta0 + (theta1 - theta0) * (i + 1) / nTheta, 2 * M_PI * j / nPhi,
                         2 * M_PI * (j + 1) / nPhi);
  return sum;
}

// ---- goodness of fit -----------------------------------------------------------------------

// One draw: false when the sampler produced no direction that the pdf describes (a failed or a
// delta sample); u is (u0, u1, u2), u0 for picking a component where there are several.
using DirectionDraw = std::function<bool(Float u0, const Point2f& u, Vector3f* w)>;

struct FitResult {
  double chi2 = 0, pValue = 1;  // pValue: the smaller of the chi-square and pooled-tail tests
  int dof = 0;
  int64_t samples = 0, failed = 0;
  double pdfIntegral = 0;  // integral of the pdf over the sphere
  int64_t pdfEvaluations = 0;
  std::string summary() const {
    std::ostringstream s;
    s << "chi2 " << chi2 << " dof " << dof << " p " << pValue << "; failed " << failed << "/"
      << samples << "; integral of pdf " << pdfIntegral << " (" << pdfEvaluations
      << " evaluations)";
    return s.str();
  }
};

// Histograms nSamples draws over nTheta x nPhi cells in (theta, phi) (nTheta even puts the
// horizon on a cell border) plus one cell for failed draws, and compares them with the pdf
// integrated over each cell (failed draws expected with probability 1 - integral). Cells expected
// to receive fewer than 5 draws are pooled; if the pool is still below 5, its count is judged by
// the Poisson upper tail instead, and the case's p-value is twice the smaller of the two.
inline FitResult chiSquareFit(const DirectionDraw& draw,
                              const std::function<double(const Vector3f&)>& pdf, int64_t nSamples,
                              uint64_t seed, int nTheta = 20, int nPhi = 40) {
  FitResult r;
  r.samples = nSamples;
  const int nCells = nTheta * nPhi;
  std::vector<double> observed(nCells + 1, 0), expected(nCells + 1, 0);
  RNG rng(seed);
  for (int64_t s = 0; s < nSamples; ++s) {
    Float u0 = rng.uniformFloat();
    Point2f u(rng.uniformFloat(), rng.uniformFloat());
    Vector3f w;
    if (!draw(u0, u, &w)) {
      observed[nCells] += 1;
      continue;
    }
    double len = std::sqrt(double(w.x) * w.x + double(w.y) * w.y + double(w.z) * w.z);
    double theta = std::acos(std::clamp(w.z / len, -1.0, 1.0));
    double phi = std::atan2(double(w.y), double(w.x));
    if (phi < 0) phi += 2 * M_PI;
    int it = std::min(nTheta - 1, int(theta / M_PI * nTheta));
    int ip = std::min(nPhi - 1, int(phi / (2 * M_PI) * nPhi));
    observed[it * nPhi + ip] += 1;
  }
  r.failed = int64_t(observed[nCells]);
  // Tolerances against the counts: a relative 1e-5 of a cell's expectation E adds at most
  // 1e-10 E to chi2, and 1e-9 absolute is 1e-3 of a sample per cell at 1M samples.
  Cubature c([&](double t, double p) { return pdf(directionFromAngles(t, p)) * std::sin(t); }, 1e-5,
             1e-9, 2, 10);
  double total = 0;
  for (int it = 0; it < nTheta; ++it)
    for (int ip = 0; ip < nPhi; ++ip) {
      double p = c.integrate(M_PI * it / nTheta, M_PI * (it + 1) / nTheta, 2 * M_PI * ip / nPhi,
                             2 * M_PI * (ip + 1) / nPhi);
      total += p;
      expected[it * nPhi + ip] = p * double(nSamples);
    }
  r.pdfIntegral = total;
  r.pdfEvaluations = c.evaluations();
  expected[nCells] = std::max(0.0, 1 - total) * double(nSamples);

  double pooledObs = 0, pooledExp = 0;
  int cells = 0;
  for (int i = 0; i <= nCells; ++i) {
    if (expected[i] < 5) {
      pooledObs += observed[i];
      pooledExp += expected[i];
      continue;
    }
    r.chi2 += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
    if (std::getenv("CANDELA_DUMP_CELLS"))
      std::printf("cell %d (theta %d phi %d): observed %.0f expected %.2f\n", i, i / nPhi, i % nPhi,
                  observed[i], expected[i]);
    ++cells;
  }
  double poolP = 1;
  if (pooledExp >= 5) {
    r.chi2 += (pooledObs - pooledExp) * (pooledObs - pooledExp) / pooledExp;
    ++cells;
  } else {
    poolP = poissonUpperTail(int64_t(pooledObs), pooledExp);
  }
  r.dof = cells - 1;
  double chi2P = r.dof > 0 ? chiSquareSurvival(r.chi2, r.dof) : 1.0;
  // Two tests on one case: Bonferroni, so the case's false-alarm rate stays at its significance.
  r.pValue = poolP < 1 ? std::min(1.0, 2 * std::min(chi2P, poolP)) : chi2P;
  return r;
}

}  // namespace candela::stats
