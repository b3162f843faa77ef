// OpenEXR files through the OpenEXR library itself, without OpenImageIO: every render writes
// one, and OpenEXR's few libraries load in about a millisecond where OpenImageIO's 250 take
// 0.18 s. The files carry what OpenImageIO's writer gave them (channels, types, windows,
// attributes, pixel values; tests/io_oiio compares the two writers).
#pragma once

#include <optional>
#include <string>

#include "core/image_buffer.h"
#include "film/output/image_codec.h"
#include "film/output/image_output.h"

namespace candela {

// True if compression is a codec name writeExr accepts: none rle zips zip piz pxr24 b44 b44a
// dwaa dwab, the DWA ones optionally with a quality level ("dwaa:60").
bool isExrCompression(const std::string& compression);

// True if the file at path starts with OpenEXR's magic number (false if it cannot be read).
bool hasExrMagic(const std::string& path);

// Writes image to path (in place; writeExr makes it atomic): every channel under its name, 16-bit
// half where options.half except depth "Z", positions "P.*" and "samples"; the data window at the
// image's offset inside the display window; chromaticities when given; metadata as string, int
// and float attributes ("DateTime" under EXR's name, "capDate"). Throws std::exception on any
// failure.
void writeExrFile(const std::string& path, const ImageBuffer& image, const ImageMetadata& metadata,
                  const ExrOptions& options, const std::optional<Chromaticities>& chromaticities);

// Reads the first part of an OpenEXR file as 32-bit float: channels in the file's order, except
// that R, G, B and A come first within each layer (as OpenImageIO orders them). With metadata,
// also the header's string, int, float and double attributes, vectors and matrices of up to 16
// values as "name[0]"..., "chromaticities[0]" to "[7]", and "compression" by codec name ("zip");
// capDate, comments and owner under OpenImageIO's names DateTime, ImageDescription and Copyright.
// Throws std::exception if the file is not a readable OpenEXR image.
DecodedImage readExrFile(const std::string& path, ImageMetadata* metadata);

}  // namespace candela
