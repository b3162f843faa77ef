// Image files for image textures: OpenEXR, or any format OpenImageIO reads (image_reader.h),
// converted to scene_linear through OpenColorIO on load (DESIGN.md, Colour). What a file's numbers
// mean is decided by its pixel type unless the scene says otherwise ("string colorspace" on the
// texture, an OCIO name, alias or role): integer pixels (8- and 16-bit PNG, JPEG, TIFF...) are
// sRGB-encoded, floating-point pixels (EXR, HDR, float TIFF) are already scene_linear. OIIO's own
// colour-space guess is not used.
#pragma once

#include <string>

#include "core/image_buffer.h"
#include "film/output/image_output.h"

namespace candela {

// The colour space assumed for a file when the scene names none: scene_linear for floating-point
// pixels; for integer pixels the config's sRGB texture space (the first of "srgb_texture",
// "sRGB - Texture", "sRGB", "srgb" it has). Throws SceneError if the config has none of them.
std::string defaultTextureColorSpace(bool integerPixels, const ColorManagement& colorManagement);

// Reads the image at path as channels R, G, B (a one- or two-channel image as grey; alpha and
// other channels dropped), rows top first, converted from colorSpace ("": the default above) to
// the rendering space `to` ("": scene_linear; the renderer passes its --colorspace working
// space). Throws FileError naming path for a missing, unreadable or corrupt file, and SceneError
// for an unknown colour space.
ImageBuffer loadTextureImage(const std::string& path, const std::string& colorSpace,
                             const ColorManagement& colorManagement, const std::string& to = "");

}  // namespace candela
