// Reading image files: OpenEXR through the OpenEXR library, any other format through the image
// plug-in (OpenImageIO), which is loaded only then. readImage (image_output.h) and the texture
// loader both read through here.
#pragma once

#include <string>

#include "film/output/image_codec.h"

namespace candela {

// Reads path (OpenEXR if it starts with OpenEXR's magic number, whatever its name). `what` names
// the file's role in messages ("image", "texture image"). Throws FileError naming path for a
// missing, unreadable or corrupt file, or when the plug-in it needs cannot be loaded.
DecodedImage decodeImageFile(const std::string& path, ImageMetadata* metadata,
                             const std::string& what);

}  // namespace candela
