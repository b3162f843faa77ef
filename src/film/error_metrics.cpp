#include "film/error_metrics.h"

#include <algorithm>
#include <array>
#include <functional>
#include <stdexcept>
#include <vector>

namespace candela {

namespace {

struct Accumulator {
  double sq = 0, rel = 0, maxAbs = 0, relVarSq = 0, relVar = 0;
  long n = 0;
  void add(double x, double ref, double var) {
    double e = x - ref, d = ref * ref + kRelMseEpsilon;
    sq += e * e;
    rel += e * e / d;
    maxAbs = std::max(maxAbs, std::abs(e));
    relVar += var / d;
    relVarSq += 2 * (var / d) * (var / d);
    ++n;
  }
  ErrorMetrics finish() const {
    ErrorMetrics m;
    if (n == 0) return m;
    m.mse = sq / double(n);
    m.relmse = rel / double(n);
    m.rmse = std::sqrt(m.mse);
    m.maxAbsError = maxAbs;
    m.relmseFromVariance = relVar / double(n);
    m.relmseCi95 = 1.96 * std::sqrt(relVarSq) / double(n);
    return m;
  }
};

}  // namespace

ErrorMetrics compareToReference(const Film& film, const ImageBuffer& reference) {
  const Bounds2i b = film.pixelBounds();
  int ox, oy;  // where film pixel (x, y) is in the reference: (x - ox, y - oy)
  if (reference.width == film.fullResolution().x && reference.height == film.fullResolution().y) {
    ox = oy = 0;
  } else if (reference.width == b.pMax.x - b.pMin.x && reference.height == b.pMax.y - b.pMin.y) {
    ox = b.pMin.x;
    oy = b.pMin.y;
  } else {
    throw std::invalid_argument("the reference image is " + std::to_string(reference.width) + "x" +
                                std::to_string(reference.height) + ", the render " +
                                std::to_string(film.fullResolution().x) + "x" +
                                std::to_string(film.fullResolution().y));
  }
  int ch[3] = {reference.channelIndex("R"), reference.channelIndex("G"),
               reference.channelIndex("B")};
  if (ch[0] < 0 || ch[1] < 0 || ch[2] < 0)
    throw std::invalid_argument("the reference image has no R, G, B channels");
  Accumulator acc;
  for (int y = b.pMin.y; y < b.pMax.y; ++y)
    for (int x = b.pMin.x; x < b.pMax.x; ++x) {
      Point2i p(x, y);
      Spectrum v = film.pixelValue(p), var = film.pixelVariance(p);
      for (int c = 0; c < 3; ++c) acc.add(v[c], reference.at(x - ox, y - oy, ch[c]), var[c]);
    }
  return acc.finish();
}

ErrorMetrics estimateFromVariance(const Film& film) {
  const Bounds2i b = film.pixelBounds();
  Accumulator acc;
  for (int y = b.pMin.y; y < b.pMax.y; ++y)
    for (int x = b.pMin.x; x < b.pMax.x; ++x) {
      Point2i p(x, y);
      if (film.pixelSampleCount(p) < 2) {
        // One sample says nothing about the spread: the error is unknown, not zero.
        ErrorMetrics unknown;
        unknown.mse = unknown.relmse = unknown.rmse = unknown.relmseFromVariance = kInfinity;
        return unknown;
      }
      Spectrum v = film.pixelValue(p), var = film.pixelVariance(p);
      for (int c = 0; c < 3; ++c) acc.add(v[c], v[c], var[c]);
    }
  ErrorMetrics m = acc.finish();
  // With the image as its own reference the squared errors are zero; report the prediction.
  m.relmse = m.relmseFromVariance;
  double meanVar = 0;
  for (int y = b.pMin.y; y < b.pMax.y; ++y)
    for (int x = b.pMin.x; x < b.pMax.x; ++x) {
      Spectrum var = film.pixelVariance(Point2i(x, y));
      meanVar += double(var[0]) + var[1] + var[2];
    }
  m.mse = acc.n > 0 ? meanVar / double(acc.n) : 0;
  m.rmse = std::sqrt(m.mse);
  return m;
}

double estimatePixelRelMse(const Film& film, const Point2i& pixel) {
  if (film.pixelSampleCount(pixel) < 2) return kInfinity;
  Spectrum v = film.pixelValue(pixel), var = film.pixelVariance(pixel);
  double sum = 0;
  for (int c = 0; c < 3; ++c) sum += double(var[c]) / (double(v[c]) * v[c] + kRelMseEpsilon);
  return sum / 3;
}

namespace {

// The R, G, B channel indices of an image, or a clear refusal naming its role.
std::array<int, 3> rgbChannels(const ImageBuffer& image, const char* role) {
  std::array<int, 3> ch{image.channelIndex("R"), image.channelIndex("G"), image.channelIndex("B")};
  if (ch[0] < 0 || ch[1] < 0 || ch[2] < 0)
    throw std::invalid_argument(std::string("the ") + role + " has no R, G, B channels");
  return ch;
}

void checkSameSize(const ImageBuffer& a, const ImageBuffer& b, const char* role) {
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument(std::string("the ") + role + " is " + std::to_string(b.width) +
                                "x" + std::to_string(b.height) + ", the image " +
                                std::to_string(a.width) + "x" + std::to_string(a.height));
}

}  // namespace

ImageComparison compareImages(const ImageBuffer& image, const ImageBuffer& reference,
                              const ImageBuffer* secondReference, int worstPixels) {
  checkSameSize(image, reference, "reference");
  if (secondReference) checkSameSize(image, *secondReference, "second reference");
  const std::array<int, 3> ci = rgbChannels(image, "image"),
                           cr = rgbChannels(reference, "reference");
  std::array<int, 3> c2{};
  if (secondReference) c2 = rgbChannels(*secondReference, "second reference");
  ImageComparison out;
  const size_t n = image.pixelCount();
  std::vector<double> pixelError;
  pixelError.reserve(n);
  double sq = 0, rel = 0, noise = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      double e = 0;
      for (int c = 0; c < 3; ++c) {
        double v = image.at(x, y, ci[c]), r = reference.at(x, y, cr[c]);
        double d = 0;
        if (secondReference) {
          double r2 = secondReference->at(x, y, c2[size_t(c)]);
          d = r - r2;
          r = (r + r2) / 2;
        }
        double denom = r * r + kRelMseEpsilon;
        sq += (v - r) * (v - r);
        e += (v - r) * (v - r) / denom;
        noise += d * d / 4 / denom;
        out.mean[c] += v / double(n);
        out.referenceMean[c] += r / double(n);
      }
      rel += e;
      pixelError.push_back(e);
    }
  const double values = 3 * double(n);
  out.relmseRaw = rel / values;
  out.referenceNoise = noise / values;
  out.relmse = out.relmseRaw - out.referenceNoise;
  out.mse = sq / values;
  out.worstPixels = std::clamp(worstPixels, 0, int(n));
  std::partial_sort(pixelError.begin(), pixelError.begin() + out.worstPixels, pixelError.end(),
                    std::greater<>());
  double worst = 0;
  for (int i = 0; i < out.worstPixels; ++i) worst += pixelError[size_t(i)];
  out.outlierShare = rel > 0 ? worst / rel : 0;
  return out;
}

}  // namespace candela
