// The narrow interface between candela and its image plug-in (candela_oiio.so, OpenImageIO):
// read any image, write an 8-bit one, assemble tiles (`candela merge`). OpenImageIO and the ~250
// libraries it pulls in (OpenCV, FFmpeg, GStreamer, DICOM, OpenVDB...) cost every process 0.18 s of
// CPU, mostly dynamic linking, and 128 MB resident, so candela loads the plug-in with dlopen only
// when a scene reads a non-EXR image or a preview is written (DESIGN.md: leave out what the scene
// does not use). Both sides are built from this tree by the same compiler; kImageCodecVersion
// guards against a stale plug-in.
#pragma once

#include <string>
#include <vector>

#include "core/image_buffer.h"

namespace candela {

// What a reader returns: the pixels as 32-bit float, with the channel names (and order) the
// file reports, and whether the file stores integers (8- and 16-bit PNG, JPEG, TIFF...), which
// the texture loader takes to be sRGB-encoded.
struct DecodedImage {
  ImageBuffer image;
  bool integerPixels = false;
};

class ImageCodec {
 public:
  virtual ~ImageCodec() = default;
  // Reads path into *out; with metadata, also the header's scalar string, float and int
  // attributes and float arrays of up to 16 values as "name[0]", "name[1]"... Returns false with
  // *error set (without the path) if the file cannot be read.
  virtual bool read(const std::string& path, DecodedImage* out, ImageMetadata* metadata,
                    std::string* error) const = 0;
  // Writes width x height pixels of 3 interleaved sRGB-encoded bytes, rows top first, to path
  // (written in place; the caller makes it atomic) in format "png" or "jpeg". Returns false with
  // *error set if it cannot.
  virtual bool writeSrgb8(const std::string& path, const std::string& format, int width, int height,
                          const unsigned char* rgb, std::string* error) const = 0;
  // Copies each tile's pixels into canvas at the tile's own data window (xOffset, yOffset; both
  // in the display window's coordinates) with ImageBufAlgo::paste: `candela merge` assembling a
  // render's tiles. canvas comes sized, placed and zeroed; the tiles have its channels, in its
  // order, and lie within it. Returns false with *error set if they do not or OpenImageIO fails.
  virtual bool pasteTiles(const std::vector<const ImageBuffer*>& tiles, ImageBuffer* canvas,
                          std::string* error) const = 0;
};

// Bumped whenever ImageCodec, DecodedImage, ImageBuffer or ImageMetadata change layout.
inline constexpr int kImageCodecVersion = 2;

}  // namespace candela

// The plug-in's one exported symbol: its codec if it was built for `version`, else nullptr.
extern "C" const candela::ImageCodec* candela_image_codec(int version);
