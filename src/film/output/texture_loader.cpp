#include "film/output/texture_loader.h"

#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <system_error>

#include "core/error.h"

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
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw FileError(path, "cannot read texture image: no such file");
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw FileError(path, "cannot read texture image: " + OIIO::geterror());
  const OIIO::ImageSpec spec = in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.depth != 1)
    throw FileError(path, "cannot read texture image: unsupported image dimensions");
  std::vector<float> pixels(size_t(spec.width) * size_t(spec.height) * size_t(spec.nchannels));
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()))
    throw FileError(path, "cannot read texture image: " + in->geterror());
  in->close();

  // R, G, B by name when the file has them, else the first three channels, else grey.
  auto channel = [&](const char* name, int fallback) {
    for (int c = 0; c < spec.nchannels; ++c)
      if (spec.channelnames.size() > size_t(c) && spec.channelnames[size_t(c)] == name) return c;
    return spec.nchannels >= 3 ? fallback : 0;
  };
  const int source[3] = {channel("R", 0), channel("G", 1), channel("B", 2)};
  ImageBuffer image(spec.width, spec.height, {"R", "G", "B"});
  for (int y = 0; y < spec.height; ++y)
    for (int x = 0; x < spec.width; ++x) {
      size_t base = (size_t(y) * size_t(spec.width) + size_t(x)) * size_t(spec.nchannels);
      for (int c = 0; c < 3; ++c) image.at(x, y, c) = pixels[base + size_t(source[c])];
    }

  bool integerPixels = !spec.format.is_floating_point();
  std::string from =
      colorSpace.empty() ? defaultTextureColorSpace(integerPixels, colorManagement) : colorSpace;
  colorManagement.convert(image, from, to.empty() ? colorManagement.sceneLinearName() : to);
  return image;
}

}  // namespace candela
