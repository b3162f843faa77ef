#include "film/film.h"

#include <cassert>
#include <cmath>

namespace candela {

namespace {
Bounds2f normalizedCrop(const Bounds2f& c) {
  Float x0 = clamp(std::min(c.pMin.x, c.pMax.x), 0, 1),
        x1 = clamp(std::max(c.pMin.x, c.pMax.x), 0, 1);
  Float y0 = clamp(std::min(c.pMin.y, c.pMax.y), 0, 1),
        y1 = clamp(std::max(c.pMin.y, c.pMax.y), 0, 1);
  return Bounds2f(Point2f(x0, y0), Point2f(x1, y1));
}
}  // namespace

Film::Film(const Point2i& fullResolution, const Bounds2f& cropWindow,
           std::unique_ptr<Filter> filter, std::string filename)
    : fullResolution_(fullResolution),
      cropWindow_(normalizedCrop(cropWindow)),
      filter_(std::move(filter)),
      filename_(std::move(filename)) {
  assert(filter_);
  pixelBounds_ = pixelBoundsOf(fullResolution, cropWindow);
  pixels_.resize(size_t(pixelBounds_.area()));
}

Bounds2i Film::pixelBoundsOf(const Point2i& fullResolution, const Bounds2f& cropWindow) {
  Bounds2f crop = normalizedCrop(cropWindow);
  // The same ceil rule at both ends (lrt draft §8.1), so crop windows sharing an edge share the
  // pixel column or row there exactly once: a set of tiling crops renders every pixel once.
  Point2i pMin(int(std::ceil(Float(fullResolution.x) * crop.pMin.x)),
               int(std::ceil(Float(fullResolution.y) * crop.pMin.y)));
  Point2i pMax(int(std::ceil(Float(fullResolution.x) * crop.pMax.x)),
               int(std::ceil(Float(fullResolution.y) * crop.pMax.y)));
  return Bounds2i(pMin, pMax);
}

size_t Film::offset(const Point2i& p) const {
  assert(pixelBounds_.inside(p));
  size_t width = size_t(pixelBounds_.pMax.x - pixelBounds_.pMin.x);
  return size_t(p.y - pixelBounds_.pMin.y) * width + size_t(p.x - pixelBounds_.pMin.x);
}

void Film::addSample(const Point2i& pixel, const Spectrum& L, Float alpha, Float weight) {
  // pbrt-v3's per-sample clamp (pbrt 3e §7.9.2): the colour kept, the luminance limited. No
  // luminance exceeds the default, infinite limit: then it is not computed.
  if (Float y; maxSampleLuminance_ < kInfinity && (y = L.y()) > maxSampleLuminance_) {
    accumulate(pixel, L * (maxSampleLuminance_ / y), alpha, weight);
    return;
  }
  accumulate(pixel, L, alpha, weight);
}

void Film::accumulate(const Point2i& pixel, const Spectrum& L, Float alpha, Float weight) {
  if (!pixelBounds_.inside(pixel)) return;
  Pixel& px = at(pixel);
  // Double sums: many spp of widely varying radiance still average without losing low bits.
  for (int c = 0; c < 3; ++c) px.rgbSum[c] += double(weight) * double(L[c]);
  px.alphaSum += double(weight) * double(alpha);
  px.weightSum += double(weight);
  double w2 = double(weight) * double(weight);
  for (int c = 0; c < 3; ++c) {
    px.w2LSum[c] += w2 * double(L[c]);
    px.w2L2Sum[c] += w2 * double(L[c]) * double(L[c]);
  }
  px.w2Sum += w2;
  ++px.count;
}

Film::PixelSums Film::pixelSums(const Point2i& pixel) const {
  return pixelBounds_.inside(pixel) ? at(pixel) : PixelSums{};
}

void Film::addPixelSums(const Point2i& pixel, const PixelSums& s) {
  if (!pixelBounds_.inside(pixel)) return;
  Pixel& px = at(pixel);
  for (int c = 0; c < 3; ++c) {
    px.rgbSum[c] += s.rgbSum[c];
    px.w2L2Sum[c] += s.w2L2Sum[c];
    px.w2LSum[c] += s.w2LSum[c];
  }
  px.alphaSum += s.alphaSum;
  px.weightSum += s.weightSum;
  px.w2Sum += s.w2Sum;
  px.count += s.count;
}

// The AOV channels of one pixel, in aovChannelNames order.
void Film::writeAovs(const Point2i& p, float* out) const {
  const AovPixel* a = aovPixels_.empty() ? nullptr : &aovPixels_[offset(p)];
  double inv = (a && a->hitWeight != 0) ? 1 / a->hitWeight : 0;
  if (aovFlags_ & kAovAlbedo)
    for (int c = 0; c < 3; ++c) *out++ = float(a->albedo[c] * inv);
  if (aovFlags_ & kAovNormal) {
    Vector3f n(Float(a->normal[0]), Float(a->normal[1]), Float(a->normal[2]));
    if (n.lengthSquared() > 0) n = normalize(n);
    *out++ = n.x, *out++ = n.y, *out++ = n.z;
  }
  if (aovFlags_ & kAovDepth) *out++ = a->depth;
  if (aovFlags_ & kAovPosition)
    for (int c = 0; c < 3; ++c) *out++ = float(a->position[c] * inv);
  if (aovFlags_ & kAovVariance) {
    Spectrum v = pixelVariance(p);
    for (int c = 0; c < 3; ++c) *out++ = v[c];
  }
  if (aovFlags_ & kAovSamples) *out++ = float(pixelSampleCount(p));
}

Spectrum Film::pixelVariance(const Point2i& pixel) const {
  if (!pixelBounds_.inside(pixel)) return Spectrum(0);
  const Pixel& px = at(pixel);
  if (px.count < 2 || px.weightSum == 0) return Spectrum(0);
  // The mean m = sum(w L) / sum(w) has variance ~ sum(w^2 (L - m)^2) / (sum w)^2 for independent
  // samples; expanded so one pass over the samples suffices. The n/(n-1) factor makes it unbiased
  // for equal weights.
  Spectrum v;
  double n = double(px.count);
  for (int c = 0; c < 3; ++c) {
    double m = px.rgbSum[c] / px.weightSum;
    double s = px.w2L2Sum[c] - 2 * m * px.w2LSum[c] + m * m * px.w2Sum;
    v[c] = Float(std::max(0.0, s) / (px.weightSum * px.weightSum) * n / (n - 1));
  }
  return v * (scale_ * scale_);
}

long Film::pixelSampleCount(const Point2i& pixel) const {
  return pixelBounds_.inside(pixel) ? at(pixel).count : 0;
}

void Film::setPixel(const Point2i& pixel, const Spectrum& L, Float alpha) {
  if (!pixelBounds_.inside(pixel)) return;
  at(pixel) = Pixel{};
  accumulate(pixel, L, alpha, 1);
}

Spectrum Film::pixelValue(const Point2i& pixel) const {
  if (!pixelBounds_.inside(pixel)) return Spectrum(0);
  const Pixel& px = at(pixel);
  // The weighted mean, Σ w L / Σ w (lrt draft §8.1; pbrt 4e §5.4.3): with weights f/pdf from the
  // filter's importance sampling, a constant L comes out exactly constant for any filter.
  Spectrum L(0);
  if (px.weightSum != 0) {
    double inv = 1 / px.weightSum;
    L = Spectrum(Float(px.rgbSum[0] * inv), Float(px.rgbSum[1] * inv), Float(px.rgbSum[2] * inv));
  }
  if (splats_ && lightPaths_ > 0) L += splats_->sum(pixel) * Float(splatScale());
  return L * scale_;
}

SplatBuffer& Film::enableSplats() {
  return enableSplats(
      Bounds2f(Point2f(0, 0), Point2f(Float(fullResolution_.x), Float(fullResolution_.y))));
}

SplatBuffer& Film::enableSplats(const Bounds2f& sampledArea) {
  if (!splats_)
    splats_ =
        std::make_unique<SplatBuffer>(pixelBounds_, sampledArea, *filter_, maxSampleLuminance_);
  return *splats_;
}

Bounds2f Film::filterSupportArea() const {
  // Pixel x's support is [x + 1/2 - r, x + 1/2 + r]; a filter narrower than a pixel still
  // leaves the image itself to cover.
  const Vector2f r = filter_->radius();
  const Float X = Float(fullResolution_.x), Y = Float(fullResolution_.y);
  return Bounds2f(Point2f(std::min(Float(0), 0.5f - r.x), std::min(Float(0), 0.5f - r.y)),
                  Point2f(std::max(X, X - 0.5f + r.x), std::max(Y, Y - 0.5f + r.y)));
}

Float Film::pixelAlpha(const Point2i& pixel) const {
  if (!pixelBounds_.inside(pixel)) return 0;
  const Pixel& px = at(pixel);
  return px.weightSum == 0 ? Float(0) : Float(px.alphaSum / px.weightSum);
}

void Film::enableAovs(unsigned flags) {
  aovFlags_ = flags;
  if (flags & kAovGeometric) aovPixels_.assign(pixels_.size(), AovPixel());
}

void Film::addAovSample(const Point2i& pixel, const AovSample& s, Float weight) {
  if (!pixelBounds_.inside(pixel) || aovPixels_.empty() || !s.hit) return;
  AovPixel& a = aovPixels_[offset(pixel)];
  double w = weight;
  for (int c = 0; c < 3; ++c) {
    a.albedo[c] += w * s.albedo[c];
    a.normal[c] += w * s.normal[c];
    a.position[c] += w * s.position[c];
  }
  a.hitWeight += w;
  a.depth = std::min(a.depth, s.depth);
}

ImageBuffer Film::image() const {
  int width = std::max(0, pixelBounds_.pMax.x - pixelBounds_.pMin.x);
  int height = std::max(0, pixelBounds_.pMax.y - pixelBounds_.pMin.y);
  std::vector<std::string> channels = {"R", "G", "B", "A"};
  std::vector<std::string> extra = aovChannelNames(aovFlags_);
  channels.insert(channels.end(), extra.begin(), extra.end());
  ImageBuffer img(width, height, channels);
  img.xOffset = pixelBounds_.pMin.x;
  img.yOffset = pixelBounds_.pMin.y;
  img.fullWidth = fullResolution_.x;
  img.fullHeight = fullResolution_.y;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      Point2i p(pixelBounds_.pMin.x + x, pixelBounds_.pMin.y + y);
      Spectrum L = pixelValue(p);
      for (int c = 0; c < 3; ++c) img.at(x, y, c) = L[c];
      img.at(x, y, 3) = pixelAlpha(p);
      if (aovFlags_) writeAovs(p, &img.at(x, y, 4));
    }
  return img;
}

}  // namespace candela
