#include "reflection/irregular_brdf.h"

#include <charconv>
#include <fstream>
#include <sstream>

#include "core/error.h"

namespace candela {

namespace {

struct Number {
  double value;
  int line;
};

// Every number of the file with its line; '#' comments run to the end of the line.
std::vector<Number> readNumbers(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path, "cannot open the measured BRDF file");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  std::vector<Number> numbers;
  int line = 1;
  size_t i = 0;
  while (i < text.size()) {
    char c = text[i];
    if (c == '\n') {
      ++line;
      ++i;
    } else if (c == ' ' || c == '\t' || c == '\r' || c == ',') {
      ++i;
    } else if (c == '#') {
      while (i < text.size() && text[i] != '\n') ++i;
    } else {
      size_t end = i;
      while (end < text.size() && !std::isspace(static_cast<unsigned char>(text[end])) &&
             text[end] != '#' && text[end] != ',')
        ++end;
      double v = 0;
      const char* first = text.data() + i + (text[i] == '+' ? 1 : 0);
      auto [ptr, ec] = std::from_chars(first, text.data() + end, v);
      if (ec != std::errc() || ptr != text.data() + end || !std::isfinite(v))
        throw FileError(path, "line " + std::to_string(line) + ": '" + text.substr(i, end - i) +
                                  "' is not a number");
      numbers.push_back({v, line});
      i = end;
    }
  }
  return numbers;
}

Vector3f direction(double theta, double phi) {
  return sphericalDirection(Float(std::sin(theta)), Float(std::cos(theta)), Float(phi));
}

}  // namespace

PointKdTree<5>::Point IrregularBrdfTable::embed(const Vector3f& a, const Vector3f& b) {
  Float sa = std::sqrt(a.x * a.x + a.y * a.y);
  Float bx, by;
  if (sa > 0) {
    Float c = a.x / sa, s = a.y / sa;
    bx = b.x * c + b.y * s;
    by = std::abs(-b.x * s + b.y * c);
  } else {  // a at the pole: any azimuth frame is the same one; put b at azimuth 0
    bx = std::sqrt(b.x * b.x + b.y * b.y);
    by = 0;
  }
  return {sa, a.z, bx, by, b.z};
}

IrregularBrdfTable::IrregularBrdfTable(std::vector<IrregularBrdfSample> samples)
    : samples_(std::move(samples)) {
  std::vector<PointKdTree<5>::Point> points;
  points.reserve(2 * samples_.size());
  for (const IrregularBrdfSample& s : samples_) {
    points.push_back(embed(s.wi, s.wo));
    points.push_back(embed(s.wo, s.wi));
  }
  tree_ = PointKdTree<5>(std::move(points));
}

Spectrum IrregularBrdfTable::lookupOrdered(const Vector3f& a, const Vector3f& b) const {
  uint32_t index[kNeighbours];
  Float dist2[kNeighbours];
  int n = tree_.nearest(embed(a, b), kNeighbours, index, dist2);
  if (n == 0) return Spectrum(0);
  // A compact smooth kernel reaching zero just past the farthest neighbour, so that the result
  // varies continuously as neighbours enter and leave the set.
  Float h2 = dist2[n - 1] * Float(1.0001) + Float(1e-12);
  Spectrum sum(0);
  Float weightSum = 0;
  for (int i = 0; i < n; ++i) {
    Float t = 1 - dist2[i] / h2;
    Float w = t * t;
    sum += samples_[index[i] / 2].value * w;
    weightSum += w;
  }
  return weightSum > 0 ? sum / weightSum : Spectrum(0);
}

Spectrum IrregularBrdfTable::lookup(const Vector3f& wo, const Vector3f& wi) const {
  if (!sameHemisphere(wo, wi)) return Spectrum(0);
  Vector3f o = wo, i = wi;
  if (o.z < 0) {
    o.z = -o.z;
    i.z = -i.z;
  }
  return (lookupOrdered(i, o) + lookupOrdered(o, i)) * Float(0.5);
}

IrregularBrdfTable readIrregularBrdf(const std::string& path, const SpectrumToRGB& toRGB) {
  std::vector<Number> numbers = readNumbers(path);
  if (numbers.empty()) throw FileError(path, "no data in the measured BRDF file");
  double nw = numbers[0].value;
  if (nw < 1 || nw > 10000 || nw != std::floor(nw))
    throw FileError(path, "line " + std::to_string(numbers[0].line) +
                              ": the wavelength count must be a positive integer");
  size_t nLambda = size_t(nw);
  if (numbers.size() < 1 + nLambda) throw FileError(path, "the wavelength list is incomplete");
  std::vector<Float> lambda(nLambda);
  for (size_t i = 0; i < nLambda; ++i) {
    lambda[i] = Float(numbers[1 + i].value);
    if (!(lambda[i] > 0))
      throw FileError(
          path, "line " + std::to_string(numbers[1 + i].line) + ": wavelengths must be positive");
  }
  size_t first = 1 + nLambda, record = 4 + nLambda, count = numbers.size() - first;
  if (count == 0) throw FileError(path, "no samples after the wavelengths");
  if (count % record != 0)
    throw FileError(path, "the last record (line " + std::to_string(numbers.back().line) +
                              ") is incomplete: each record is 4 angles and " +
                              std::to_string(nLambda) + " values");
  std::vector<IrregularBrdfSample> samples;
  samples.reserve(count / record);
  std::vector<Float> values(nLambda);
  constexpr double kThetaMax = 1.5707963267948966 + 1e-4;
  for (size_t r = first; r < numbers.size(); r += record) {
    double thetaI = numbers[r].value, phiI = numbers[r + 1].value;
    double thetaO = numbers[r + 2].value, phiO = numbers[r + 3].value;
    if (thetaI < 0 || thetaI > kThetaMax || thetaO < 0 || thetaO > kThetaMax)
      throw FileError(path, "line " + std::to_string(numbers[r].line) +
                                ": polar angles must lie in [0, pi/2] radians");
    for (size_t i = 0; i < nLambda; ++i) values[i] = Float(numbers[r + 4 + i].value);
    Spectrum rgb = clampSpectrum(toRGB(lambda, values), 0, kInfinity);
    samples.push_back({direction(thetaI, phiI), direction(thetaO, phiO), rgb});
  }
  return IrregularBrdfTable(std::move(samples));
}

}  // namespace candela
