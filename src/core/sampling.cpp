#include "core/sampling.h"

#include <numeric>

namespace candela {

Point2f sampleUniformDiskPolar(const Point2f& u) {
  Float r = std::sqrt(u.x), theta = 2 * kPi * u.y;
  return Point2f(r * std::cos(theta), r * std::sin(theta));
}

Vector3f sampleUniformHemisphere(const Point2f& u) {
  Float z = u.x;
  Float r = safeSqrt(1 - z * z);
  Float phi = 2 * kPi * u.y;
  return Vector3f(r * std::cos(phi), r * std::sin(phi), z);
}

Vector3f sampleUniformSphere(const Point2f& u) {
  Float z = 1 - 2 * u.x;
  Float r = safeSqrt(1 - z * z);
  Float phi = 2 * kPi * u.y;
  return Vector3f(r * std::cos(phi), r * std::sin(phi), z);
}

Vector3f sampleUniformCone(const Point2f& u, Float cosThetaMax) {
  Float cosTheta = (1 - u.x) + u.x * cosThetaMax;
  Float sinTheta = safeSqrt(1 - cosTheta * cosTheta);
  Float phi = u.y * 2 * kPi;
  return Vector3f(std::cos(phi) * sinTheta, std::sin(phi) * sinTheta, cosTheta);
}

Distribution1D::Distribution1D(std::vector<Float> func)
    : func_(std::move(func)), cdf_(func_.size() + 1) {
  size_t n = func_.size();
  for (auto& f : func_) f = std::abs(f);
  cdf_[0] = 0;
  for (size_t i = 1; i <= n; ++i) cdf_[i] = cdf_[i - 1] + func_[i - 1] / Float(n);
  funcInt_ = cdf_[n];
  if (funcInt_ == 0) {
    for (size_t i = 1; i <= n; ++i) cdf_[i] = Float(i) / Float(n);
  } else {
    for (size_t i = 1; i <= n; ++i) cdf_[i] /= funcInt_;
  }
}

namespace {
// Largest index i in [0, size-2] with cdf[i] <= u.
int findInterval(const std::vector<Float>& cdf, Float u) {
  auto it = std::upper_bound(cdf.begin(), cdf.end(), u);
  int idx = int(it - cdf.begin()) - 1;
  return clamp(idx, 0, int(cdf.size()) - 2);
}
}  // namespace

Float Distribution1D::sampleContinuous(Float u, Float* pdf, int* offset) const {
  int i = findInterval(cdf_, u);
  if (offset) *offset = i;
  Float du = u - cdf_[i];
  Float width = cdf_[i + 1] - cdf_[i];
  if (width > 0) du /= width;
  if (pdf) *pdf = funcInt_ > 0 ? func_[i] / funcInt_ : Float(1);
  return std::min((Float(i) + du) / Float(count()), kOneMinusEpsilon);
}

int Distribution1D::sampleDiscrete(Float u, Float* pmf) const {
  int i = findInterval(cdf_, u);
  if (pmf) *pmf = funcInt_ > 0 ? discretePmf(i) : Float(1) / count();
  return i;
}

namespace {
std::vector<Float> rowOf(const std::vector<Float>& func, int nu, int v) {
  return std::vector<Float>(func.begin() + long(v) * nu, func.begin() + long(v + 1) * nu);
}
std::vector<Float> marginalOf(const std::vector<Float>& func, int nu, int nv) {
  std::vector<Float> m(nv);
  for (int v = 0; v < nv; ++v) {
    Float s = 0;
    for (int u = 0; u < nu; ++u) s += std::abs(func[size_t(v) * nu + u]);
    m[v] = s / Float(nu);
  }
  return m;
}
}  // namespace

Distribution2D::Distribution2D(const std::vector<Float>& func, int nu, int nv)
    : marginal_(marginalOf(func, nu, nv)) {
  conditional_.reserve(nv);
  for (int v = 0; v < nv; ++v) conditional_.emplace_back(rowOf(func, nu, v));
}

Point2f Distribution2D::sampleContinuous(const Point2f& u, Float* pdf) const {
  Float pdfs[2];
  int v;
  Float d1 = marginal_.sampleContinuous(u.y, &pdfs[1], &v);
  Float d0 = conditional_[v].sampleContinuous(u.x, &pdfs[0]);
  *pdf = pdfs[0] * pdfs[1];
  return Point2f(d0, d1);
}

Float Distribution2D::pdf(const Point2f& p) const {
  int nu = conditional_[0].count(), nv = marginal_.count();
  int iu = clamp(int(p.x * nu), 0, nu - 1);
  int iv = clamp(int(p.y * nv), 0, nv - 1);
  if (marginal_.integral() == 0) return 1;
  return conditional_[iv].func(iu) / marginal_.integral();
}

}  // namespace candela
