#include "support/fourier_bsdf_writer.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace candela::test {

namespace {

void put(std::string& out, const void* p, size_t n) { out.append(static_cast<const char*>(p), n); }
void putU32(std::string& out, uint32_t v) { put(out, &v, 4); }
void putF32(std::string& out, float v) { put(out, &v, 4); }

// Integral of a Catmull-Rom spline through (x, y) from x[0] to each node (the writer's cdf; the
// reader recomputes its own), interval by interval with the Hermite cubic's exact integral
// (f0 + f1) / 2 + (d0 - d1) / 12 in units of the width.
std::vector<float> splineIntegrals(const std::vector<float>& x, const std::vector<double>& y) {
  size_t n = x.size();
  std::vector<float> cdf(n, 0);
  double sum = 0;
  for (size_t i = 0; i + 1 < n; ++i) {
    double w = double(x[i + 1]) - x[i], f0 = y[i], f1 = y[i + 1];
    double d0 =
        i > 0 && x[i + 1] > x[i - 1] ? w * (f1 - y[i - 1]) / (x[i + 1] - x[i - 1]) : f1 - f0;
    double d1 = i + 2 < n && x[i + 2] > x[i] ? w * (y[i + 2] - f0) / (x[i + 2] - x[i]) : f1 - f0;
    sum += w * ((f0 + f1) / 2 + (d0 - d1) / 12);
    cdf[i + 1] = float(sum);
  }
  return cdf;
}

}  // namespace

std::vector<float> splitUniformNodes(int nHalf) {
  std::vector<float> mu;
  for (int k = nHalf; k >= 1; --k) mu.push_back(-float(k) / float(nHalf));
  mu.push_back(-0.0f);
  mu.push_back(0.0f);
  for (int k = 1; k <= nHalf; ++k) mu.push_back(float(k) / float(nHalf));
  return mu;
}

std::string fourierBsdfFileBytes(const FourierBsdfModel& model, const std::vector<float>& mu,
                                 const std::string& metadata) {
  size_t n = mu.size();
  int nc = model.nChannels;
  std::vector<uint32_t> offsets(n * n), lengths(n * n);
  std::vector<float> coeffs;
  std::vector<double> a0(n * n, 0);
  uint32_t mMax = 0;
  // Cells by mu_o, then mu_i (pbrt 3e §8.6's table layout).
  for (size_t o = 0; o < n; ++o)
    for (size_t i = 0; i < n; ++i) {
      std::vector<double> a = model.coefficients(mu[i], mu[o]);
      if (a.size() != size_t(nc * model.orders))
        throw std::logic_error("model returned the wrong number of coefficients");
      int m = 0;
      for (int c = 0; c < nc; ++c)
        for (int k = 0; k < model.orders; ++k)
          if (a[size_t(c * model.orders + k)] != 0) m = std::max(m, k + 1);
      size_t cell = o * n + i;
      offsets[cell] = uint32_t(coeffs.size());
      lengths[cell] = uint32_t(m);
      mMax = std::max(mMax, uint32_t(m));
      for (int c = 0; c < nc; ++c)
        for (int k = 0; k < m; ++k) coeffs.push_back(float(a[size_t(c * model.orders + k)]));
      a0[cell] = m > 0 ? a[0] : 0;
    }
  std::string out;
  put(out, "SCATFUN", 7);
  out.push_back(char(1));
  putU32(out, 1);  // flags: a BSDF
  putU32(out, uint32_t(n));
  putU32(out, uint32_t(coeffs.size()));
  putU32(out, mMax);
  putU32(out, uint32_t(nc));
  putU32(out, 1);  // nBases
  putU32(out, uint32_t(metadata.size()));
  putU32(out, 0);  // nParameters
  putU32(out, 0);  // nParameterValues
  putF32(out, model.eta);
  for (int k = 0; k < 4; ++k) putF32(out, 0);  // alpha[2], unused[2]
  for (float m : mu) putF32(out, m);
  // Per mu_o, the integral of a_0 over mu_i.
  for (size_t o = 0; o < n; ++o) {
    std::vector<double> row(a0.begin() + std::ptrdiff_t(o * n),
                            a0.begin() + std::ptrdiff_t(o * n + n));
    std::vector<float> cdf = splineIntegrals(mu, row);
    for (size_t i = 0; i < n; ++i) putF32(out, cdf[i]);
  }
  for (size_t cell = 0; cell < n * n; ++cell) {
    putU32(out, offsets[cell]);
    putU32(out, lengths[cell]);
  }
  for (float c : coeffs) putF32(out, c);
  out += metadata;
  return out;
}

void writeBytes(const std::string& path, const std::string& bytes) {
  std::ofstream f(path, std::ios::binary);
  f.write(bytes.data(), std::streamsize(bytes.size()));
  if (!f) throw std::runtime_error("cannot write " + path);
}

bool isReflection(double muI, double muO) { return std::signbit(muI) != std::signbit(muO); }

FourierBsdfModel lambertianModel(double rho) {
  FourierBsdfModel m;
  m.coefficients = [rho](double muI, double muO) {
    return std::vector<double>{isReflection(muI, muO) ? rho / M_PI * std::abs(muI) : 0.0};
  };
  return m;
}

FourierBsdfModel fejerModel(double rhoR, double rhoG, double rhoB, int n) {
  FourierBsdfModel m;
  m.nChannels = 3;
  m.orders = n;
  m.coefficients = [=](double muI, double muO) {
    std::vector<double> a(size_t(3 * n), 0.0);
    if (!isReflection(muI, muO)) return a;
    double rho[3] = {0.212671 * rhoR + 0.715160 * rhoG + 0.072169 * rhoB, rhoR, rhoB};
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < n; ++k)
        a[size_t(c * n + k)] =
            rho[c] / M_PI * std::abs(muI) * (k == 0 ? 1.0 : 2.0 * (1.0 - double(k) / n));
    return a;
  };
  return m;
}

FourierBsdfModel diffuseTransmitterModel(double rho, double tau, float eta) {
  FourierBsdfModel m;
  m.eta = eta;
  m.coefficients = [=](double muI, double muO) {
    return std::vector<double>{(isReflection(muI, muO) ? rho : tau) / M_PI * std::abs(muI)};
  };
  return m;
}

}  // namespace candela::test
