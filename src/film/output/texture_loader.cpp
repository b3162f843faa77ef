#include "film/output/texture_loader.h"

#include "core/error.h"
#include "film/output/image_reader.h"

namespace candela {

std::string defaultTextureColorSpace(bool integerPixels, const ColorManagement& colorManagement) {
  if (!integerPixels) return colorManagement.sceneLinearName();
  for (const char* name : {"srgb_texture", "sRGB - Texture", "sRGB", "srgb"})
    if (colorManagement.hasColorSpace(name)) return name;
  throw SceneError("the OpenColorIO config '" + colorManagement.configPath() +
                   "' has no sRGB texture colour space for 8- and 16-bit images; name the "
                   "image's colour space with \"string colorspace\"");
}

ImageBuffer loadTextureImage(const std::string& path, const std::string& colorSpace,
                             const ColorManagement& colorManagement, const std::string& to) {
  const DecodedImage decoded = decodeImageFile(path, nullptr, "texture image");
  const ImageBuffer& file = decoded.image;

  // R, G, B by name when the file has them, else the first three channels, else grey.
  auto channel = [&](const char* name, int fallback) {
    const int c = file.channelIndex(name);
    if (c >= 0) return c;
    return file.channelCount() >= 3 ? fallback : 0;
  };
  const int source[3] = {channel("R", 0), channel("G", 1), channel("B", 2)};
  ImageBuffer image(file.width, file.height, {"R", "G", "B"});
  for (int y = 0; y < file.height; ++y)
    for (int x = 0; x < file.width; ++x)
      for (int c = 0; c < 3; ++c) image.at(x, y, c) = file.at(x, y, source[c]);

  std::string from = colorSpace.empty()
                         ? defaultTextureColorSpace(decoded.integerPixels, colorManagement)
                         : colorSpace;
  colorManagement.convert(image, from, to.empty() ? colorManagement.sceneLinearName() : to);
  return image;
}

}  // namespace candela
