#include "app/tile_paste.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <stdexcept>

namespace candela {

ImageBuffer pasteTiles(const std::vector<const ImageBuffer*>& tiles, const Bounds2i& region,
                       int fullWidth, int fullHeight) {
  if (tiles.empty() || region.empty()) throw std::invalid_argument("no tiles to paste");
  const std::vector<std::string>& channels = tiles.front()->channels;
  const int nc = int(channels.size());
  OIIO::ImageSpec spec(region.pMax.x - region.pMin.x, region.pMax.y - region.pMin.y, nc,
                       OIIO::TypeDesc::FLOAT);
  spec.x = region.pMin.x;
  spec.y = region.pMin.y;
  spec.full_x = spec.full_y = 0;
  spec.full_width = fullWidth;
  spec.full_height = fullHeight;
  spec.channelnames = channels;
  OIIO::ImageBuf canvas(spec, OIIO::InitializePixels::Yes);
  for (const ImageBuffer* tile : tiles) {
    if (tile->channels != channels || !tile->consistent())
      throw std::invalid_argument("the tiles' channels differ");
    OIIO::ImageSpec tileSpec(tile->width, tile->height, nc, OIIO::TypeDesc::FLOAT);
    // Wrapped, not copied; paste only reads it.
    const OIIO::ImageBuf source(tileSpec, const_cast<float*>(tile->data.data()));
    // paste puts the source's (0, 0) at (x, y) of the canvas's pixel coordinates.
    if (!OIIO::ImageBufAlgo::paste(canvas, tile->xOffset, tile->yOffset, 0, 0, source))
      throw std::runtime_error("cannot paste a tile: " + canvas.geterror());
  }
  ImageBuffer out(spec.width, spec.height, channels);
  out.xOffset = spec.x;
  out.yOffset = spec.y;
  out.fullWidth = fullWidth;
  out.fullHeight = fullHeight;
  if (!canvas.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, out.data.data()))
    throw std::runtime_error("cannot read the pasted image: " + canvas.geterror());
  return out;
}

}  // namespace candela
