#include "film/film_sums.h"

#include <cmath>

namespace candela {

namespace {

constexpr int kSums = 13;
// In the order sumsOf lists them.
const char* const kSumNames[kSums] = {"wR",   "wG",  "wB",  "wA",  "w",  "w2RR", "w2GG",
                                      "w2BB", "w2R", "w2G", "w2B", "w2", "n"};

void sumsOf(const Film::PixelSums& s, double* out) {
  for (int c = 0; c < 3; ++c) out[c] = s.rgbSum[c];
  out[3] = s.alphaSum;
  out[4] = s.weightSum;
  for (int c = 0; c < 3; ++c) out[5 + c] = s.w2L2Sum[c];
  for (int c = 0; c < 3; ++c) out[8 + c] = s.w2LSum[c];
  out[11] = s.w2Sum;
  out[12] = double(s.count);
}

Film::PixelSums pixelSumsOf(const double* in) {
  Film::PixelSums s;
  for (int c = 0; c < 3; ++c) s.rgbSum[c] = in[c];
  s.alphaSum = in[3];
  s.weightSum = in[4];
  for (int c = 0; c < 3; ++c) s.w2L2Sum[c] = in[5 + c];
  for (int c = 0; c < 3; ++c) s.w2LSum[c] = in[8 + c];
  s.w2Sum = in[11];
  s.count = long(std::llround(in[12]));
  return s;
}

Bounds2i dataWindow(const ImageBuffer& image) {
  return Bounds2i(Point2i(image.xOffset, image.yOffset),
                  Point2i(image.xOffset + image.width, image.yOffset + image.height));
}

}  // namespace

std::vector<std::string> filmSumChannelNames() {
  std::vector<std::string> names;
  for (const char* n : kSumNames) {
    names.push_back(std::string("sums.") + n + ".hi");
    names.push_back(std::string("sums.") + n + ".lo");
  }
  return names;
}

void appendFilmSums(const Film& film, ImageBuffer& image) {
  if (!(dataWindow(image) == film.pixelBounds()) || !image.consistent())
    throw std::invalid_argument("the image is not the film's pixel bounds");
  const std::vector<std::string> added = filmSumChannelNames();
  const size_t oldStride = image.channels.size(), stride = oldStride + added.size();
  std::vector<float> data(image.pixelCount() * stride);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const size_t i = size_t(y) * size_t(image.width) + size_t(x);
      for (size_t c = 0; c < oldStride; ++c) data[i * stride + c] = image.data[i * oldStride + c];
      double sums[kSums];
      sumsOf(film.pixelSums(Point2i(image.xOffset + x, image.yOffset + y)), sums);
      float* out = &data[i * stride + oldStride];
      for (int k = 0; k < kSums; ++k) {
        const float hi = float(sums[k]);
        if (!std::isfinite(hi) && std::isfinite(sums[k]))
          throw std::invalid_argument("a pixel's sum " + std::to_string(sums[k]) +
                                      " exceeds the float range");
        out[2 * k] = hi;
        out[2 * k + 1] = float(sums[k] - double(hi));
      }
    }
  image.channels.insert(image.channels.end(), added.begin(), added.end());
  image.data = std::move(data);
}

void addFilmSums(const ImageBuffer& image, Film& film) {
  const std::vector<std::string> names = filmSumChannelNames();
  std::vector<int> index;
  for (const std::string& n : names) {
    index.push_back(image.channelIndex(n));
    if (index.back() < 0) throw std::invalid_argument("no channel '" + n + "'");
  }
  const Bounds2i window = dataWindow(image);
  if (!(intersect(window, film.pixelBounds()) == window))
    throw std::invalid_argument("its pixels reach outside the image");
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      double sums[kSums];
      for (int k = 0; k < kSums; ++k)
        sums[k] = double(image.at(x, y, index[2 * k])) + double(image.at(x, y, index[2 * k + 1]));
      film.addPixelSums(Point2i(image.xOffset + x, image.yOffset + y), pixelSumsOf(sums));
    }
}

}  // namespace candela
