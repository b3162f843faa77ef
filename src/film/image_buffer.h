// A multi-channel float image in memory, and metadata for its file: what the film produces and
// the image writers consume. Plain data, so nothing here needs OpenImageIO.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace candela {

struct ImageBuffer {
  int width = 0, height = 0;
  std::vector<std::string> channels;  // e.g. R, G, B, A, albedo.R, ...
  std::vector<float> data;            // interleaved, row-major, top row first
  // Where this image sits in the full frame (EXR data window within the display window).
  int xOffset = 0, yOffset = 0;
  int fullWidth = 0, fullHeight = 0;  // 0: same as width/height

  ImageBuffer() = default;
  ImageBuffer(int w, int h, std::vector<std::string> ch)
      : width(w), height(h), channels(std::move(ch)), data(size_t(w) * h * channels.size(), 0.f) {}
  int channelCount() const { return int(channels.size()); }
  float& at(int x, int y, int c) { return data[(size_t(y) * width + x) * channels.size() + c]; }
  float at(int x, int y, int c) const {
    return data[(size_t(y) * width + x) * channels.size() + c];
  }
  // Index of a channel by name, or -1.
  int channelIndex(const std::string& name) const {
    for (size_t i = 0; i < channels.size(); ++i)
      if (channels[i] == name) return int(i);
    return -1;
  }
};

struct ImageMetadata {
  std::vector<std::pair<std::string, std::string>> strings;
  std::vector<std::pair<std::string, float>> floats;
  std::vector<std::pair<std::string, int>> ints;
};

}  // namespace candela
