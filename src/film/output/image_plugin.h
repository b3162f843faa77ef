// Finds and loads the image plug-in (candela_oiio.so, film/output/image_codec.h) on first use.
#pragma once

#include <string>
#include <vector>

#include "film/output/image_codec.h"

namespace candela {

// Where the plug-in is looked for, in order: $CANDELA_OIIO_PLUGIN alone when set; else next to
// the running executable, then where the build put it (CANDELA_OIIO_PLUGIN_BUILD_PATH).
std::vector<std::string> imagePluginCandidates();

// The plug-in's codec, loaded with dlopen by the first call (later calls return it at once).
// Throws FileError naming the path when the plug-in is missing (naming every place looked in),
// cannot be loaded, or was built for another version of candela.
const ImageCodec& imagePlugin();

}  // namespace candela
