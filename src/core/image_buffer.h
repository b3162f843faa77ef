// A multi-channel float image in memory, and metadata for its file: what the film produces and
// the image writers consume. Plain data, so nothing here needs OpenImageIO or OpenColorIO.
#pragma once

#include <cassert>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace candela {

struct ImageBuffer {
  int width = 0, height = 0;
  std::vector<std::string> channels;  // e.g. R, G, B, A, albedo.R, ..., Z
  std::vector<float> data;            // interleaved, row-major, top row first
  // Where this image sits in the full frame (EXR data window within the display window).
  int xOffset = 0, yOffset = 0;
  int fullWidth = 0, fullHeight = 0;  // 0: same as width/height

  ImageBuffer() = default;
  ImageBuffer(int w, int h, std::vector<std::string> ch)
      : width(w), height(h), channels(std::move(ch)), data(pixelCount() * channels.size(), 0.f) {}

  int channelCount() const { return int(channels.size()); }
  size_t pixelCount() const {
    return size_t(width > 0 ? width : 0) * size_t(height > 0 ? height : 0);
  }
  // True when the sizes agree with each other: what a writer checks before trusting data.
  bool consistent() const {
    return width > 0 && height > 0 && !channels.empty() &&
           data.size() == pixelCount() * channels.size();
  }
  int displayWidth() const { return fullWidth > 0 ? fullWidth : width; }
  int displayHeight() const { return fullHeight > 0 ? fullHeight : height; }

  size_t offset(int x, int y, int c) const {
    assert(x >= 0 && x < width && y >= 0 && y < height && c >= 0 && c < channelCount());
    return (size_t(y) * size_t(width) + size_t(x)) * channels.size() + size_t(c);
  }
  float& at(int x, int y, int c) { return data[offset(x, y, c)]; }
  float at(int x, int y, int c) const { return data[offset(x, y, c)]; }

  // Index of the channel with this exact name, or -1. Files may store channels in any order
  // (OpenEXR sorts them by name), so readers look channels up by name, never by position.
  int channelIndex(const std::string& name) const {
    for (size_t i = 0; i < channels.size(); ++i)
      if (channels[i] == name) return int(i);
    return -1;
  }
  // The mean of the first three channels (R, G, B as the film makes them) over every pixel; 0 for
  // an empty image.
  double rgbMean() const {
    double sum = 0;
    size_t n = 0;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x)
        for (int c = 0; c < 3 && c < channelCount(); ++c, ++n) sum += at(x, y, c);
    return n > 0 ? sum / double(n) : 0;
  }
  // The alpha channel ("A", or "alpha"), or -1.
  int alphaChannel() const {
    int a = channelIndex("A");
    return a >= 0 ? a : channelIndex("alpha");
  }
};

// Header attributes written with an image, e.g. {"Software", "candela 0.1"}, {"candela:spp", 64}.
struct ImageMetadata {
  std::vector<std::pair<std::string, std::string>> strings;
  std::vector<std::pair<std::string, float>> floats;
  std::vector<std::pair<std::string, int>> ints;

  // Lookups by name; nullptr when absent.
  const std::string* findString(const std::string& name) const { return find(strings, name); }
  const float* findFloat(const std::string& name) const { return find(floats, name); }
  const int* findInt(const std::string& name) const { return find(ints, name); }

 private:
  template <typename T>
  static const T* find(const std::vector<std::pair<std::string, T>>& list,
                       const std::string& name) {
    for (const auto& [key, value] : list)
      if (key == name) return &value;
    return nullptr;
  }
};

}  // namespace candela
