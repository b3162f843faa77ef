// OpenEXR output through OpenEXR (exr_file.h); previews through the image plug-in (OpenImageIO,
// loaded only for them); both written atomically.
#include "film/output/image_output.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <exception>
#include <filesystem>
#include <functional>
#include <system_error>

#include "core/error.h"
#include "film/output/exr_file.h"
#include "film/output/image_plugin.h"

namespace fs = std::filesystem;

namespace candela {

namespace {

// --- atomic writing ---------------------------------------------------------------------------

// A name in the target's directory (so the final rename stays on one file system and is atomic),
// hidden, and unique per process and call so concurrent writers never collide.
fs::path temporaryPathFor(const fs::path& target) {
  static std::atomic<unsigned long> counter{0};
  // Built with += rather than "." + string: GCC 12 warns falsely (-Wrestrict) about the latter.
  std::string name = ".";
  name += target.filename().string();
  name += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter.fetch_add(1));
  return target.parent_path() / name;
}

void removeQuietly(const fs::path& p) {
  std::error_code ec;
  fs::remove(p, ec);
}

// Lets `write` fill a temporary file (it throws on failure) and renames it to path. On any
// failure the temporary file is removed and FileError names path.
void writeAtomically(const std::string& path,
                     const std::function<void(const std::string&)>& write) {
  const fs::path target(path);
  // Checked first only for a clearer message; the write below is what really decides.
  checkImagePath(path);
  const fs::path tmp = temporaryPathFor(target);
  std::string error;
  try {
    write(tmp.string());
  } catch (const std::exception& e) {
    error = std::string("cannot write image: ") + e.what();
  }
  if (error.empty()) {
    std::error_code ec;
    fs::rename(tmp, target, ec);
    if (ec) error = "cannot rename temporary file '" + tmp.string() + "': " + ec.message();
  }
  if (!error.empty()) {
    removeQuietly(tmp);
    throw FileError(path, error);
  }
}

void checkChannels(const std::string& path, const ImageBuffer& image) {
  if (!image.consistent())
    throw FileError(path, "cannot write image: buffer of " + std::to_string(image.width) + "x" +
                              std::to_string(image.height) + " pixels, " +
                              std::to_string(image.channels.size()) + " channels and " +
                              std::to_string(image.data.size()) + " values is inconsistent");
  for (size_t i = 0; i < image.channels.size(); ++i) {
    if (image.channels[i].empty()) throw FileError(path, "cannot write image: empty channel name");
    for (size_t j = 0; j < i; ++j)
      if (image.channels[i] == image.channels[j])
        throw FileError(path, "cannot write image: duplicate channel '" + image.channels[i] + "'");
  }
}

std::string lowerExtension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  for (char& ch : ext) ch = char(std::tolower(static_cast<unsigned char>(ch)));
  return ext;
}

}  // namespace

// --- chromaticities ---------------------------------------------------------------------------

std::optional<Chromaticities> knownChromaticities(const std::string& colorSpace) {
  // Rec.709 / sRGB primaries with D65 white (ITU-R BT.709).
  static const Chromaticities rec709{{0.64f, 0.33f, 0.30f, 0.60f, 0.15f, 0.06f, 0.3127f, 0.3290f}};
  // ACES AP1 primaries and the ACES white (~D60), SMPTE ST 2065-1 / S-2014-004.
  static const Chromaticities ap1{
      {0.713f, 0.293f, 0.165f, 0.830f, 0.128f, 0.044f, 0.32168f, 0.33767f}};
  // ACES AP0 primaries (ACES2065-1).
  static const Chromaticities ap0{
      {0.7347f, 0.2653f, 0.0f, 1.0f, 0.0001f, -0.0770f, 0.32168f, 0.33767f}};
  // Canonical names and aliases of the default config, for callers without a config at hand.
  for (const char* n : {"lin_rec709", "Linear Rec.709 (sRGB)", "linear", "Linear", "lin_srgb"})
    if (colorSpace == n) return rec709;
  for (const char* n : {"acescg", "ACEScg", "ACES - ACEScg"})
    if (colorSpace == n) return ap1;
  for (const char* n : {"aces2065_1", "ACES2065-1", "ACES - ACES2065-1"})
    if (colorSpace == n) return ap0;
  return std::nullopt;
}

// --- writers ----------------------------------------------------------------------------------

void writeExr(const std::string& path, const ImageBuffer& image, const ImageMetadata& metadata,
              const ExrOptions& options) {
  checkChannels(path, image);
  if (!isExrCompression(options.compression))
    throw FileError(path, "unknown EXR compression '" + options.compression +
                              "' (expected zip, zips, piz, dwaa, dwab, rle, pxr24, b44, b44a or "
                              "none)");
  const std::optional<Chromaticities> chromaticities =
      options.chromaticities ? options.chromaticities : knownChromaticities(options.colorSpace);
  writeAtomically(path, [&](const std::string& file) {
    writeExrFile(file, image, metadata, options, chromaticities);
  });
}

void checkImagePath(const std::string& path) {
  const fs::path target(path);
  if (target.filename().empty()) throw FileError(path, "not a file name");
  const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw FileError(path, "cannot write image: directory '" + dir.string() + "' does not exist");
  if (fs::is_directory(target, ec)) throw FileError(path, "cannot write image: is a directory");
}

std::string previewFormat(const std::string& path) {
  const std::string ext = lowerExtension(path);
  if (ext == ".png") return "png";
  if (ext == ".jpg" || ext == ".jpeg") return "jpeg";
  throw FileError(path, "unsupported preview format '" + ext + "' (expected .png or .jpg)");
}

void writePreview(const std::string& path, const ImageBuffer& sceneLinear,
                  const ColorManagement& colorManagement, const std::string& display,
                  const std::string& view) {
  const std::string format = previewFormat(path);
  if (!sceneLinear.consistent()) throw FileError(path, "cannot write preview: empty image");

  // RGB only; a one- or two-channel image is shown as grey from its first channel.
  ImageBuffer rgb(sceneLinear.width, sceneLinear.height, {"R", "G", "B"});
  const size_t n = sceneLinear.pixelCount(), stride = sceneLinear.channels.size();
  for (size_t i = 0; i < n; ++i)
    for (size_t c = 0; c < 3; ++c)
      rgb.data[i * 3 + c] = sceneLinear.data[i * stride + (stride >= 3 ? c : 0)];
  colorManagement.toDisplay(rgb, display, view);

  std::vector<unsigned char> bytes(rgb.data.size());
  for (size_t i = 0; i < bytes.size(); ++i) {
    float v = rgb.data[i];
    v = std::isnan(v) ? 0.f : std::clamp(v, 0.f, 1.f);
    bytes[i] = static_cast<unsigned char>(std::lround(v * 255.f));
  }

  const ImageCodec& codec = imagePlugin();
  writeAtomically(path, [&](const std::string& file) {
    std::string error;
    if (!codec.writeSrgb8(file, format, rgb.width, rgb.height, bytes.data(), &error))
      throw std::runtime_error(error);
  });
}

}  // namespace candela
