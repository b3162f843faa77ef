// Image files and colour management: scene-linear OpenEXR output (with AOV channels, a
// chromaticities attribute and metadata), 8-bit previews through an OpenColorIO display view, and
// image reading. Every writer is atomic: it writes a temporary file next to the target and renames
// it, so a crash or error never leaves a partial image under the final name.
//
// OpenEXR goes through the OpenEXR library; previews and other formats through the image plug-in
// (OpenImageIO), which is loaded only when one is written or read (image_codec.h). The header
// names no OpenEXR, OpenImageIO or OpenColorIO type.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/image_buffer.h"

namespace candela {

// CIE xy of the red, green and blue primaries and of the white point, in that order
// (the layout of OpenEXR's "chromaticities" attribute).
struct Chromaticities {
  std::array<float, 8> xy{};
};

// Chromaticities of the colour spaces candela knows by name ("lin_rec709", "acescg" and their
// aliases in the default config); std::nullopt for any other.
std::optional<Chromaticities> knownChromaticities(const std::string& colorSpace);

struct ExrOptions {
  bool half = false;                // 16-bit half floats instead of 32-bit floats ("Z" stays float)
  std::string compression = "zip";  // zip piz dwaa none (also zips rle pxr24 b44 b44a dwab)
  std::string colorSpace = "lin_rec709";  // what RGB means; picks the chromaticities attribute
  // Overrides the chromaticities looked up from colorSpace (e.g. from a custom OCIO config).
  std::optional<Chromaticities> chromaticities = std::nullopt;
};

// Writes image (all its channels, under their names) to an OpenEXR file at path. "A" is marked as
// the alpha channel and "Z" as depth. metadata becomes header attributes. Throws FileError naming
// path on any failure; then no file is created at path (an existing one is left untouched) and
// no temporary file remains.
void writeExr(const std::string& path, const ImageBuffer& image, const ImageMetadata& metadata,
              const ExrOptions& options = {});

// An OpenColorIO config and the conversions candela needs from it.
class ColorManagement {
 public:
  // configPath empty: $OCIO, else candela's default config (CANDELA_DEFAULT_OCIO_CONFIG).
  // Throws FileError naming the config when it cannot be read or is invalid.
  explicit ColorManagement(const std::string& configPath = "");
  ~ColorManagement();
  ColorManagement(ColorManagement&&) noexcept;
  ColorManagement& operator=(ColorManagement&&) noexcept;

  const std::string& configPath() const { return path_; }
  // True if name is a colour space, alias or role in the config.
  bool hasColorSpace(const std::string& name) const;
  // The canonical name of a colour space, alias or role; throws SceneError if unknown.
  std::string canonicalName(const std::string& name) const;
  // The canonical name of the scene_linear role ("lin_rec709" in the default config).
  std::string sceneLinearName() const;
  // Chromaticities of a colour space (after resolving aliases and roles), if candela knows them.
  std::optional<Chromaticities> chromaticities(const std::string& colorSpace) const;
  std::vector<std::string> displays() const;
  std::vector<std::string> views(const std::string& display) const;

  // Converts the first three channels of image (as RGB) from one colour space to another; the
  // other channels (alpha, AOVs) are untouched. Throws SceneError for unknown names and
  // std::invalid_argument for an image with fewer than three channels.
  void convert(ImageBuffer& image, const std::string& from, const std::string& to) const;
  // Converts the first three channels from scene_linear to a display's view (e.g. "sRGB",
  // "Standard"). Values are not clamped.
  void toDisplay(ImageBuffer& image, const std::string& display, const std::string& view) const;

 private:
  struct Impl;
  std::string path_;
  std::unique_ptr<Impl> impl_;
};

// What writeExr and writePreview check before writing, for callers that must know before any
// work is done: path names a file whose directory exists (FileError naming path otherwise); for a
// preview also that its extension is .png, .jpg or .jpeg. Returns the preview's format name.
void checkImagePath(const std::string& path);
std::string previewFormat(const std::string& path);

// Writes an 8-bit RGB preview (PNG or JPEG, chosen by the extension of path) of a scene-linear
// image through a display view: converts, clamps to [0, 1], quantises. Alpha is dropped: the
// preview is for looking at. Atomic and throwing like writeExr.
void writePreview(const std::string& path, const ImageBuffer& sceneLinear,
                  const ColorManagement& colorManagement, const std::string& display = "sRGB",
                  const std::string& view = "Standard");

// Reads an OpenEXR file, or any image OpenImageIO can read, as 32-bit float, with the channel
// names the file reports (in an order that may differ by format: look channels up by name). If
// metadata is given, it receives the header's scalar string, float and int attributes under their
// names; float arrays of up to 16 values (such as "chromaticities") as floats "name[0]",
// "name[1]"... Throws FileError if the file is missing, unreadable or corrupt, or when it needs the
// image plug-in and that cannot be loaded.
ImageBuffer readImage(const std::string& path, ImageMetadata* metadata = nullptr);

}  // namespace candela
