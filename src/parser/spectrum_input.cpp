#include "parser/spectrum_input.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "core/cie_data.h"
#include "core/error.h"
#include "core/number_file.h"
#include "core/read_file.h"

namespace candela {

namespace {

// Sum of the tabulated y(λ) at 1 nm steps: dividing by it makes a constant SPD of 1 have Y = 1.
double cieYSum() {
  static const double sum = [] {
    double s = 0;
    for (int i = 0; i < kCieSamples; ++i) s += kCieY[i];
    return s;
  }();
  return sum;
}

// XYZ of an SPD given as values at the CIE table's wavelengths (lrt draft §5.1.2: the
// integrals of S(λ) against x, y, z, here as 1 nm Riemann sums).
void integrateAgainstCie(const double* spd, double xyz[3]) {
  double x = 0, y = 0, z = 0;
  for (int i = 0; i < kCieSamples; ++i) {
    x += spd[i] * kCieX[i];
    y += spd[i] * kCieY[i];
    z += spd[i] * kCieZ[i];
  }
  double norm = cieYSum();
  xyz[0] = x / norm;
  xyz[1] = y / norm;
  xyz[2] = z / norm;
}

using Mat3 = std::array<std::array<double, 3>, 3>;

Mat3 mul3(const Mat3& a, const Mat3& b) {
  Mat3 r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) r[i][j] += a[i][k] * b[k][j];
  return r;
}

Mat3 inverse3(const Mat3& m) {
  double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
               m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      // Cofactor of (j, i), cyclic form.
      int a0 = (j + 1) % 3, a1 = (j + 2) % 3, b0 = (i + 1) % 3, b1 = (i + 2) % 3;
      r[i][j] = (m[a0][b0] * m[a1][b1] - m[a0][b1] * m[a1][b0]) / det;
    }
  return r;
}

// Bradford chromatic adaptation from the white of a constant SPD (equal energy, E) to the D65
// white of linear Rec.709 (the XYZ of RGB (1, 1, 1)): cone-like responses are scaled so that one
// white maps onto the other (von Kries).
const Mat3& reflectanceAdaptation() {
  static const Mat3 m = [] {
    const Mat3 bradford = {{{0.8951, 0.2664, -0.1614},  // standard Bradford
                            {-0.7502, 1.7135, 0.0367},  // cone response
                            {0.0389, -0.0685, 1.0296}}};
    double one[kCieSamples];
    std::fill(one, one + kCieSamples, 1.0);
    double src[3];
    integrateAgainstCie(one, src);
    Float dstF[3];
    Spectrum(1).toXYZ(dstF);
    double dst[3] = {dstF[0], dstF[1], dstF[2]};
    double srcCone[3] = {0, 0, 0}, dstCone[3] = {0, 0, 0};
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) {
        srcCone[i] += bradford[i][k] * src[k];
        dstCone[i] += bradford[i][k] * dst[k];
      }
    Mat3 diag{};
    for (int i = 0; i < 3; ++i) diag[i][i] = dstCone[i] / srcCone[i];
    return mul3(inverse3(bradford), mul3(diag, bradford));
  }();
  return m;
}

// The SPD through the samples evaluated at every CIE wavelength (linear interpolation; clamped
// outside the samples' range). samples must be sorted by wavelength and non-empty.
void resampleToCie(const std::vector<SpectrumSample>& s, double* out) {
  size_t j = 0;
  for (int i = 0; i < kCieSamples; ++i) {
    double lambda = kCieLambdaStart + i;
    if (lambda <= s.front().lambda) {
      out[i] = s.front().value;
      continue;
    }
    if (lambda >= s.back().lambda) {
      out[i] = s.back().value;
      continue;
    }
    while (j + 1 < s.size() && s[j + 1].lambda < lambda) ++j;
    const SpectrumSample &a = s[j], &b = s[j + 1];
    double span = double(b.lambda) - a.lambda;
    double t = span > 0 ? (lambda - a.lambda) / span : 0;
    out[i] = (1 - t) * a.value + t * b.value;
  }
}

Spectrum xyzToRGB(const double xyz[3], SpectrumUse use) {
  double v[3] = {xyz[0], xyz[1], xyz[2]};
  if (use == SpectrumUse::Reflectance) {
    const Mat3& m = reflectanceAdaptation();
    for (int i = 0; i < 3; ++i) v[i] = m[i][0] * xyz[0] + m[i][1] * xyz[1] + m[i][2] * xyz[2];
  }
  return Spectrum::fromXYZ(Float(v[0]), Float(v[1]), Float(v[2]));
}

}  // namespace

SpectrumUse spectrumUseForParameter(const std::string& paramName) {
  // pbrt-v2 lights: point/spot/goniometric/projection "I", distant/infinite/area "L"; volume
  // regions' emission "Le" (lrt draft §12-13).
  if (paramName == "L" || paramName == "I" || paramName == "Le") return SpectrumUse::Illuminant;
  return SpectrumUse::Reflectance;
}

void spectrumSamplesToXYZ(std::vector<SpectrumSample> samples, Float xyz[3]) {
  if (samples.empty()) {
    xyz[0] = xyz[1] = xyz[2] = 0;
    return;
  }
  std::stable_sort(
      samples.begin(), samples.end(),
      [](const SpectrumSample& a, const SpectrumSample& b) { return a.lambda < b.lambda; });
  double spd[kCieSamples], v[3];
  resampleToCie(samples, spd);
  integrateAgainstCie(spd, v);
  for (int i = 0; i < 3; ++i) xyz[i] = Float(v[i]);
}

Spectrum spectrumSamplesToRGB(std::vector<SpectrumSample> samples, SpectrumUse use) {
  Float xyz[3];
  spectrumSamplesToXYZ(std::move(samples), xyz);
  double v[3] = {xyz[0], xyz[1], xyz[2]};
  return xyzToRGB(v, use);
}

double planck(double lambdaNm, double kelvin) {
  const double h = 6.62607015e-34, c = 2.99792458e8, kb = 1.380649e-23;  // SI, exact
  double l = lambdaNm * 1e-9;
  double e = h * c / (l * kb * kelvin);
  if (e > 700) return 0;  // exp would overflow; the radiance is 0 in double precision
  return 2 * h * c * c / (l * l * l * l * l) / std::expm1(e);
}

Spectrum blackbodyToRGB(Float kelvin, Float scale) {
  // Normalised by the peak: B(λ) / B(λmax) depends only on x = λmax / λ (Wien: λmax T = b), as
  // x^5 (e^a - 1) / (e^(a x) - 1) with a = hc / (k b); this stays finite for any T > 0.
  const double b = 2.897771955e-3;  // Wien's displacement constant, m K
  const double h = 6.62607015e-34, c = 2.99792458e8, kb = 1.380649e-23;
  const double a = h * c / (kb * b);
  double lambdaMaxNm = b / double(kelvin) * 1e9;
  double spd[kCieSamples];
  for (int i = 0; i < kCieSamples; ++i) {
    double x = lambdaMaxNm / (kCieLambdaStart + i);
    spd[i] = (a * x > 700) ? 0.0 : std::pow(x, 5) * std::expm1(a) / std::expm1(a * x);
    spd[i] *= scale;
  }
  double xyz[3];
  integrateAgainstCie(spd, xyz);
  return xyzToRGB(xyz, SpectrumUse::Illuminant);
}

std::vector<SpectrumSample> parseSpectrumFile(std::string_view text, const std::string& path) {
  std::vector<double> numbers = parseNumberFile(text, path);
  if (numbers.empty()) throw FileError(path, "spectrum file has no values");
  if (numbers.size() % 2 != 0)
    throw FileError(path, "spectrum file has an odd number of values (" +
                              std::to_string(numbers.size()) +
                              "); expected wavelength-value pairs");
  std::vector<SpectrumSample> samples;
  for (size_t i = 0; i < numbers.size(); i += 2)
    samples.push_back({Float(numbers[i]), Float(numbers[i + 1])});
  return samples;
}

std::vector<SpectrumSample> readSpectrumFile(const std::string& path) {
  return parseSpectrumFile(readWholeFile(path), path);
}

}  // namespace candela
