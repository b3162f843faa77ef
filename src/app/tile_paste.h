// The one place `candela merge` uses OpenImageIO: assembling tiles into one image. Plain data in
// and out, so that it can move into the image plug-in with the rest of OpenImageIO.
#pragma once

#include <vector>

#include "core/bounds.h"
#include "film/image_buffer.h"

namespace candela {

// An image of region (its data window; display window fullWidth x fullHeight) with every tile's
// pixels copied to its own data window (ImageBufAlgo::paste). The tiles must have the channels of
// the first, in its order, and lie within region; pixels no tile covers are zero. Throws
// std::invalid_argument on mismatched channels and std::runtime_error when OpenImageIO fails.
ImageBuffer pasteTiles(const std::vector<const ImageBuffer*>& tiles, const Bounds2i& region,
                       int fullWidth, int fullHeight);

}  // namespace candela
