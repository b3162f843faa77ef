#include "reflection/irregular_brdf.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "core/error.h"
#include "core/read_file.h"

namespace candela {

namespace {

struct Number {
  double value;
  int line;
};

// Every number of the text with its line; '#' comments run to the end of the line.
std::vector<Number> readNumbers(std::string_view text, const std::string& path) {
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
        throw FileError(path, "line " + std::to_string(line) + ": '" +
                                  std::string(text.substr(i, end - i)) + "' is not a number");
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

PointKdTree<3>::Point IrregularBrdfTable::reduce(const Vector3f& a, const Vector3f& b) {
  // |phi_a - phi_b| rather than the difference wrapped into [0, 2 pi): the same after folding,
  // and bit-identical for (a, b) and (b, a). A pole has azimuth 0, as in the book, whatever the
  // signs of its zero x and y (atan2(-0, -0) is -pi).
  auto phi = [](const Vector3f& w) {
    return w.x == 0 && w.y == 0 ? Float(0) : std::atan2(w.y, w.x);
  };
  Float dphi = std::abs(phi(a) - phi(b));
  if (dphi > kPi) dphi = 2 * kPi - dphi;
  return {sinTheta(a) * sinTheta(b), dphi / kPi, cosTheta(a) * cosTheta(b)};
}

IrregularBrdfTable::IrregularBrdfTable(std::vector<IrregularBrdfSample> samples)
    : samples_(std::move(samples)) {
  std::vector<PointKdTree<3>::Point> points;
  points.reserve(samples_.size());
  for (const IrregularBrdfSample& s : samples_) points.push_back(reduce(s.wi, s.wo));
  tree_ = PointKdTree<3>(std::move(points));
}

IrregularBrdfEstimate IrregularBrdfTable::estimate(const Vector3f& wo, const Vector3f& wi) const {
  IrregularBrdfEstimate e;
  if (!sameHemisphere(wo, wi)) return e;
  PointKdTree<3>::Point q = reduce(wi, wo);
  // The book searches radius after radius; the radius it stops at is the first of the doubling
  // sequence that holds the kEnoughSamples-th nearest sample strictly inside, so one
  // nearest-neighbour query finds it and one fixed-radius query gathers the samples.
  uint32_t index[kEnoughSamples];
  Float dist2[kEnoughSamples];
  int n = tree_.nearest(q, kEnoughSamples, index, dist2);
  bool enough = n == kEnoughSamples;
  Float r2 = kStartRadius2;
  while (!(enough && dist2[kEnoughSamples - 1] < r2) && !(r2 > kLastRadius2)) r2 *= 2;
  e.radius2 = r2;
  // Double weights: exp(-100 d^2) leaves float's range for d^2 > 1.04, inside the last radius.
  double sum[3] = {0, 0, 0}, weightSum = 0;
  tree_.forEachWithin(q, r2, [&](uint32_t i, Float d2) {
    double w = std::exp(-kFalloff * double(d2));
    for (int c = 0; c < 3; ++c) sum[c] += w * double(samples_[i].value[c]);
    weightSum += w;
    ++e.found;
  });
  if (e.found == 0) return e;  // the book divides 0 by 0 here
  for (int c = 0; c < 3; ++c) e.value[c] = Float(std::max(0.0, sum[c]) / weightSum);
  return e;
}

IrregularBrdfTable readIrregularBrdf(const std::string& path, const SpectrumToRGB& toRGB) {
  return parseIrregularBrdf(readWholeFile(path), path, toRGB);
}

IrregularBrdfTable parseIrregularBrdf(std::string_view text, const std::string& path,
                                      const SpectrumToRGB& toRGB) {
  std::vector<Number> numbers = readNumbers(text, path);
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
    Spectrum rgb = toRGB(lambda, values);
    // Values beyond float's range (the reader takes any finite double) or near its limit give
    // an infinite colour, which lookups would average into infinity or NaN.
    if (!std::isfinite(rgb[0]) || !std::isfinite(rgb[1]) || !std::isfinite(rgb[2]))
      throw FileError(path, "line " + std::to_string(numbers[r].line) +
                                ": the record's values give a colour beyond the float range");
    samples.push_back({direction(thetaI, phiI), direction(thetaO, phiO), rgb});
  }
  return IrregularBrdfTable(std::move(samples));
}

}  // namespace candela
