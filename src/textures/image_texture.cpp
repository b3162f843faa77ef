#include "textures/image_texture.h"

namespace candela {

namespace {

// The channel indices that hold R, G, B (the same index three times for a grey image).
void rgbChannels(const ImageBuffer& image, int c[3]) {
  int r = image.channelIndex("R"), g = image.channelIndex("G"), b = image.channelIndex("B");
  if (r >= 0 && g >= 0 && b >= 0) {
    c[0] = r, c[1] = g, c[2] = b;
  } else if (image.channelCount() >= 3) {
    c[0] = 0, c[1] = 1, c[2] = 2;
  } else {
    c[0] = c[1] = c[2] = 0;
  }
}

Float adjust(Float v, Float scale, Float gamma) {
  v *= scale;
  return gamma == 1 ? v : std::pow(std::max(v, Float(0)), gamma);
}

Spectrum pixel(const ImageBuffer& image, const int c[3], int x, int y) {
  return {image.at(x, y, c[0]), image.at(x, y, c[1]), image.at(x, y, c[2])};
}

}  // namespace

std::vector<Spectrum> spectrumTexels(const ImageBuffer& image, Float scale, Float gamma) {
  int c[3];
  rgbChannels(image, c);
  std::vector<Spectrum> texels;
  texels.reserve(image.pixelCount());
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      Spectrum v = pixel(image, c, x, y);
      texels.emplace_back(adjust(v[0], scale, gamma), adjust(v[1], scale, gamma),
                          adjust(v[2], scale, gamma));
    }
  return texels;
}

std::vector<Float> floatTexels(const ImageBuffer& image, Float scale, Float gamma) {
  int c[3];
  rgbChannels(image, c);
  bool grey = c[0] == c[1] && c[1] == c[2];
  std::vector<Float> texels;
  texels.reserve(image.pixelCount());
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      // A grey image's value itself: its luminance weights would sum to 1 only to rounding.
      Float v = grey ? image.at(x, y, c[0]) : pixel(image, c, x, y).y();
      texels.push_back(adjust(v, scale, gamma));
    }
  return texels;
}

}  // namespace candela
