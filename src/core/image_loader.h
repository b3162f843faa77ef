// How plug-ins below the io layer read an image file (image textures, light maps): a function the
// build hands them (candela_io's loadTextureImage in the renderer: OpenImageIO + OpenColorIO), so
// that nothing but io knows image formats or colour management.
#pragma once

#include <functional>
#include <string>

#include "core/image_buffer.h"

namespace candela {

// Reads the image at path converted from colorSpace to the rendering space (scene_linear, or the
// --colorspace working space). colorSpace "" is the default rule (sRGB for integer pixels,
// scene_linear for float ones); kSrgbEncoded or kStoredLinear the space the default rule gives
// integer or float pixels, whatever the file's pixel type; anything else an OCIO name. Throws
// naming the path.
using ImageLoader =
    std::function<ImageBuffer(const std::string& path, const std::string& colorSpace)>;

// pbrt-v3's "bool gamma" true and false (not OCIO names: '<' cannot start one).
inline constexpr const char* kSrgbEncoded = "<srgb-encoded>";
inline constexpr const char* kStoredLinear = "<stored-linear>";

}  // namespace candela
