#include "film/error_metrics.h"

#include <stdexcept>

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

}  // namespace candela
