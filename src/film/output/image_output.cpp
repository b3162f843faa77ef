// OpenEXR and preview output through OpenImageIO, colour management through OpenColorIO.
#include "film/output/image_output.h"

#include <unistd.h>

#include <OpenColorIO/OpenColorIO.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <system_error>

#include "core/error.h"

namespace OCIO = OCIO_NAMESPACE;
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

// Opens an OIIO writer for `format` on a temporary file, lets `write` fill it, and renames it to
// path. On any failure the temporary file is removed and FileError names path.
void writeAtomically(const std::string& path, const std::string& format,
                     const OIIO::ImageSpec& spec,
                     const std::function<bool(OIIO::ImageOutput&)>& write) {
  const fs::path target(path);
  // Checked first only for a clearer message; the open below is what really decides.
  checkImagePath(path);
  std::error_code ec;

  const fs::path tmp = temporaryPathFor(target);
  std::string error;
  try {
    auto out = OIIO::ImageOutput::create(format);
    if (!out) {
      error = "no image writer for format '" + format + "': " + OIIO::geterror();
    } else if (!out->open(tmp.string(), spec)) {
      error = "cannot open for writing: " + out->geterror();
    } else {
      bool ok = write(*out);
      if (!ok) error = "cannot write image: " + out->geterror();
      if (!out->close() && ok) error = "cannot finish writing image: " + out->geterror();
    }
  } catch (const std::exception& e) {
    error = std::string("cannot write image: ") + e.what();
  }
  if (error.empty()) {
    fs::rename(tmp, target, ec);
    if (ec) error = "cannot rename temporary file '" + tmp.string() + "': " + ec.message();
  }
  if (!error.empty()) {
    removeQuietly(tmp);
    throw FileError(path, error);
  }
}

// --- EXR --------------------------------------------------------------------------------------

bool isExrCompression(const std::string& compression) {
  const size_t colon = compression.find(':');
  const std::string base = compression.substr(0, colon);
  bool known = false;
  for (const char* name :
       {"none", "rle", "zips", "zip", "piz", "pxr24", "b44", "b44a", "dwaa", "dwab"})
    known = known || base == name;
  if (!known || colon == std::string::npos) return known;
  // Only the DWA codecs take a quality suffix ("dwaa:45").
  const std::string level = compression.substr(colon + 1);
  return (base == "dwaa" || base == "dwab") && !level.empty() &&
         std::all_of(level.begin(), level.end(), [](char ch) { return ch >= '0' && ch <= '9'; });
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

// --- OCIO helpers -----------------------------------------------------------------------------

std::string resolveConfigPath(const std::string& configPath) {
  if (!configPath.empty()) return configPath;
  if (const char* env = std::getenv("OCIO"); env && *env) return env;
#ifdef CANDELA_DEFAULT_OCIO_CONFIG
  return CANDELA_DEFAULT_OCIO_CONFIG;
#else
  return "";
#endif
}

// Applies a CPU processor to the first three channels of every pixel, via a packed RGB copy
// (OCIO wants contiguous RGB; the image may have any number of channels).
void applyToRgb(const OCIO::ConstCPUProcessorRcPtr& cpu, ImageBuffer& image) {
  const size_t n = image.pixelCount(), stride = image.channels.size();
  std::vector<float> rgb(n * 3);
  for (size_t i = 0; i < n; ++i)
    for (size_t c = 0; c < 3; ++c) rgb[i * 3 + c] = image.data[i * stride + c];
  OCIO::PackedImageDesc desc(rgb.data(), long(image.width), long(image.height), 3);
  cpu->apply(desc);
  for (size_t i = 0; i < n; ++i)
    for (size_t c = 0; c < 3; ++c) image.data[i * stride + c] = rgb[i * 3 + c];
}

void requireRgb(const ImageBuffer& image) {
  if (!image.consistent() || image.channels.size() < 3)
    throw std::invalid_argument("colour conversion needs a consistent image with >= 3 channels");
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

  OIIO::ImageSpec spec(image.width, image.height, image.channelCount(),
                       options.half ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT);
  spec.channelnames = image.channels;
  const int z = image.channelIndex("Z");
  if (options.half) {
    // Depth, positions and sample counts keep 32 bits even in a half image: half's 11-bit
    // significand and 65504 maximum are fine for colour, not for distances, coordinates or counts
    // above 2048.
    spec.channelformats.assign(size_t(image.channelCount()), OIIO::TypeDesc::HALF);
    bool anyFloat = false;
    for (size_t c = 0; c < image.channels.size(); ++c) {
      const std::string& name = image.channels[c];
      if (name == "Z" || name.rfind("P.", 0) == 0 || name == "samples") {
        spec.channelformats[c] = OIIO::TypeDesc::FLOAT;
        anyFloat = true;
      }
    }
    if (!anyFloat) spec.channelformats.clear();
  }
  spec.alpha_channel = image.alphaChannel();
  spec.z_channel = z;
  // Data window inside the display window, so crop renders composite in place.
  spec.x = image.xOffset;
  spec.y = image.yOffset;
  spec.full_x = 0;
  spec.full_y = 0;
  spec.full_width = image.displayWidth();
  spec.full_height = image.displayHeight();
  spec.attribute("compression", options.compression);
  spec.attribute("oiio:ColorSpace", options.colorSpace);
  spec.attribute("candela:colorSpace", options.colorSpace);
  if (auto chroma =
          options.chromaticities ? options.chromaticities : knownChromaticities(options.colorSpace))
    spec.attribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8), chroma->xy.data());
  for (const auto& [name, value] : metadata.strings) spec.attribute(name, value);
  for (const auto& [name, value] : metadata.floats) spec.attribute(name, value);
  for (const auto& [name, value] : metadata.ints) spec.attribute(name, value);

  writeAtomically(path, "openexr", spec, [&](OIIO::ImageOutput& out) {
    return out.write_image(OIIO::TypeDesc::FLOAT, image.data.data());
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

  OIIO::ImageSpec spec(rgb.width, rgb.height, 3, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:ColorSpace", "sRGB");  // the sRGB view's encoding; PNG gets an sRGB chunk
  if (format == "jpeg") spec.attribute("CompressionQuality", 95);
  writeAtomically(path, format, spec, [&](OIIO::ImageOutput& out) {
    return out.write_image(OIIO::TypeDesc::UINT8, bytes.data());
  });
}

// --- reader -----------------------------------------------------------------------------------

ImageBuffer readImage(const std::string& path, ImageMetadata* metadata) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw FileError(path, "cannot read image: no such file");
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw FileError(path, "cannot read image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.depth != 1)
    throw FileError(path, "cannot read image: unsupported image dimensions");

  ImageBuffer image;
  image.width = spec.width;
  image.height = spec.height;
  image.channels = spec.channelnames;
  image.channels.resize(size_t(spec.nchannels));
  image.xOffset = spec.x;
  image.yOffset = spec.y;
  image.fullWidth = spec.full_width;
  image.fullHeight = spec.full_height;
  image.data.assign(image.pixelCount() * size_t(spec.nchannels), 0.f);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.data.data()))
    throw FileError(path, "cannot read image: " + in->geterror());
  in->close();

  if (metadata) {
    for (const OIIO::ParamValue& p : spec.extra_attribs) {
      const std::string name = p.name().string();
      const OIIO::TypeDesc t = p.type();
      const int count = int(t.numelements()) * int(t.aggregate) * p.nvalues();
      if (t == OIIO::TypeString) {
        metadata->strings.emplace_back(name, p.get_string());
      } else if (t.basetype == OIIO::TypeDesc::FLOAT || t.basetype == OIIO::TypeDesc::HALF ||
                 t.basetype == OIIO::TypeDesc::DOUBLE) {
        if (count == 1)
          metadata->floats.emplace_back(name, p.get_float());
        else if (count <= 16)
          for (int i = 0; i < count; ++i)
            metadata->floats.emplace_back(name + "[" + std::to_string(i) + "]",
                                          p.get_float_indexed(i));
      } else if (count == 1 &&
                 (t.basetype == OIIO::TypeDesc::INT || t.basetype == OIIO::TypeDesc::UINT ||
                  t.basetype == OIIO::TypeDesc::INT16 || t.basetype == OIIO::TypeDesc::UINT16 ||
                  t.basetype == OIIO::TypeDesc::INT8 || t.basetype == OIIO::TypeDesc::UINT8)) {
        metadata->ints.emplace_back(name, p.get_int());
      }
    }
  }
  return image;
}

// --- ColorManagement --------------------------------------------------------------------------

struct ColorManagement::Impl {
  OCIO::ConstConfigRcPtr config;
};

ColorManagement::ColorManagement(const std::string& configPath)
    : path_(resolveConfigPath(configPath)), impl_(std::make_unique<Impl>()) {
  if (path_.empty()) throw FileError("<no OCIO config>", "no OpenColorIO config given");
  std::error_code ec;
  if (!fs::is_regular_file(path_, ec)) throw FileError(path_, "OpenColorIO config not found");
  try {
    impl_->config = OCIO::Config::CreateFromFile(path_.c_str());
    impl_->config->validate();
  } catch (const OCIO::Exception& e) {
    throw FileError(path_, std::string("cannot load OpenColorIO config: ") + e.what());
  }
}

ColorManagement::~ColorManagement() = default;
ColorManagement::ColorManagement(ColorManagement&&) noexcept = default;
ColorManagement& ColorManagement::operator=(ColorManagement&&) noexcept = default;

bool ColorManagement::hasColorSpace(const std::string& name) const {
  return !name.empty() && impl_->config->getColorSpace(name.c_str()) != nullptr;
}

std::string ColorManagement::canonicalName(const std::string& name) const {
  auto cs = name.empty() ? nullptr : impl_->config->getColorSpace(name.c_str());
  if (!cs)
    throw SceneError("unknown colour space '" + name + "' in OpenColorIO config '" + path_ + "'");
  return cs->getName();
}

std::string ColorManagement::sceneLinearName() const {
  return canonicalName(OCIO::ROLE_SCENE_LINEAR);
}

std::optional<Chromaticities> ColorManagement::chromaticities(const std::string& colorSpace) const {
  if (!hasColorSpace(colorSpace)) return std::nullopt;
  return knownChromaticities(canonicalName(colorSpace));
}

std::vector<std::string> ColorManagement::displays() const {
  std::vector<std::string> result;
  for (int i = 0; i < impl_->config->getNumDisplays(); ++i)
    result.emplace_back(impl_->config->getDisplay(i));
  return result;
}

std::vector<std::string> ColorManagement::views(const std::string& display) const {
  std::vector<std::string> result;
  for (int i = 0; i < impl_->config->getNumViews(display.c_str()); ++i)
    result.emplace_back(impl_->config->getView(display.c_str(), i));
  return result;
}

void ColorManagement::convert(ImageBuffer& image, const std::string& from,
                              const std::string& to) const {
  requireRgb(image);
  const std::string src = canonicalName(from), dst = canonicalName(to);
  if (src == dst) return;
  try {
    auto processor = impl_->config->getProcessor(src.c_str(), dst.c_str());
    applyToRgb(processor->getDefaultCPUProcessor(), image);
  } catch (const OCIO::Exception& e) {
    throw SceneError("cannot convert colour space '" + from + "' to '" + to + "': " + e.what());
  }
}

void ColorManagement::toDisplay(ImageBuffer& image, const std::string& display,
                                const std::string& view) const {
  requireRgb(image);
  auto known = views(display);
  if (std::find(known.begin(), known.end(), view) == known.end())
    throw SceneError("unknown display/view '" + display + "'/'" + view +
                     "' in OpenColorIO config '" + path_ + "'");
  try {
    auto processor = impl_->config->getProcessor(OCIO::ROLE_SCENE_LINEAR, display.c_str(),
                                                 view.c_str(), OCIO::TRANSFORM_DIR_FORWARD);
    applyToRgb(processor->getDefaultCPUProcessor(), image);
  } catch (const OCIO::Exception& e) {
    throw SceneError("cannot apply display '" + display + "' view '" + view + "': " + e.what());
  }
}

}  // namespace candela
