// Test tool for the farm's scripts: compares two images value by value, in units in the last place
// of 32-bit floats, or prints one metadata attribute of an image.
//   candela_image_diff A B [--max-ulps N]   exit 0 when both have the same windows and channels
//                                            and every value is within N ulps (default 0: the
//                                            same bits); prints how many differ and by how much
//   candela_image_diff --get FILE KEY        prints the attribute (string, int or float), or for
//                                            KEY dataWindow the pixels: x0 y0 x1 y1 (exclusive)
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

#include "film/output/image_output.h"

using namespace candela;

namespace {

// Floats mapped to integers in the order of their values, so that adjacent floats differ by 1.
int64_t ordered(float f) {
  int32_t i;
  std::memcpy(&i, &f, sizeof i);
  return i < 0 ? int64_t(INT32_MIN) - int64_t(i) : int64_t(i);
}

int get(const std::string& path, const std::string& key) {
  ImageMetadata m;
  const ImageBuffer image = readImage(path, &m);
  if (key == "dataWindow")
    return std::printf("%d %d %d %d\n", image.xOffset, image.yOffset, image.xOffset + image.width,
                       image.yOffset + image.height),
           0;
  if (const std::string* s = m.findString(key)) return std::printf("%s\n", s->c_str()), 0;
  if (const int* i = m.findInt(key)) return std::printf("%d\n", *i), 0;
  if (const float* f = m.findFloat(key)) return std::printf("%.9g\n", double(*f)), 0;
  std::fprintf(stderr, "%s: no attribute %s\n", path.c_str(), key.c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) try {
  if (argc == 4 && std::string(argv[1]) == "--get") return get(argv[2], argv[3]);
  if (argc != 3 && !(argc == 5 && std::string(argv[3]) == "--max-ulps")) {
    std::fprintf(stderr, "usage: candela_image_diff A B [--max-ulps N] | --get FILE KEY\n");
    return 2;
  }
  const int64_t maxUlps = argc == 5 ? std::stoll(argv[4]) : 0;
  const ImageBuffer a = readImage(argv[1]), b = readImage(argv[2]);
  if (a.width != b.width || a.height != b.height || a.xOffset != b.xOffset ||
      a.yOffset != b.yOffset || a.displayWidth() != b.displayWidth() ||
      a.displayHeight() != b.displayHeight()) {
    std::printf("DIFFERENT windows: %dx%d at (%d, %d) of %dx%d vs %dx%d at (%d, %d) of %dx%d\n",
                a.width, a.height, a.xOffset, a.yOffset, a.displayWidth(), a.displayHeight(),
                b.width, b.height, b.xOffset, b.yOffset, b.displayWidth(), b.displayHeight());
    return 1;
  }
  if (a.channels.size() != b.channels.size()) {
    std::printf("DIFFERENT channel counts: %zu vs %zu\n", a.channels.size(), b.channels.size());
    return 1;
  }
  size_t values = 0, differing = 0;
  int64_t worst = 0;
  std::string worstChannel;
  for (int c = 0; c < a.channelCount(); ++c) {
    const int cb = b.channelIndex(a.channels[size_t(c)]);
    if (cb < 0) {
      std::printf("DIFFERENT channels: %s is only in %s\n", a.channels[size_t(c)].c_str(), argv[1]);
      return 1;
    }
    for (int y = 0; y < a.height; ++y)
      for (int x = 0; x < a.width; ++x) {
        const float va = a.at(x, y, c), vb = b.at(x, y, cb);
        ++values;
        if (std::memcmp(&va, &vb, sizeof va) == 0 || (std::isnan(va) && std::isnan(vb))) continue;
        ++differing;
        const int64_t d = std::llabs(ordered(va) - ordered(vb));
        if (d > worst) worst = d, worstChannel = a.channels[size_t(c)];
      }
  }
  std::printf("%zu values in %d channels: %zu differ%s%s\n", values, a.channelCount(), differing,
              differing ? ", by at most ulps " : "",
              differing ? (std::to_string(worst) + " (" + worstChannel + ")").c_str() : "");
  return worst <= maxUlps ? 0 : 1;
} catch (const std::exception& e) {
  std::fprintf(stderr, "%s\n", e.what());
  return 2;
}
