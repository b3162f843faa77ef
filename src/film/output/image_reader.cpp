#include "film/output/image_reader.h"

#include <exception>
#include <filesystem>
#include <system_error>

#include "core/error.h"
#include "film/output/exr_file.h"
#include "film/output/image_output.h"
#include "film/output/image_plugin.h"

namespace candela {

DecodedImage decodeImageFile(const std::string& path, ImageMetadata* metadata,
                             const std::string& what) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw FileError(path, "cannot read " + what + ": no such file");
  if (hasExrMagic(path)) {
    try {
      return readExrFile(path, metadata);
    } catch (const std::exception& e) {
      throw FileError(path, "cannot read " + what + ": " + e.what());
    }
  }
  DecodedImage decoded;
  std::string error;
  if (!imagePlugin().read(path, &decoded, metadata, &error))
    throw FileError(path, "cannot read " + what + ": " + error);
  return decoded;
}

ImageBuffer readImage(const std::string& path, ImageMetadata* metadata) {
  return decodeImageFile(path, metadata, "image").image;
}

}  // namespace candela
