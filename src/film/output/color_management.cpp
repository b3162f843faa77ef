// Colour management through OpenColorIO (image_output.h, ColorManagement).
#include <OpenColorIO/OpenColorIO.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "core/error.h"
#include "film/output/image_output.h"

namespace OCIO = OCIO_NAMESPACE;
namespace fs = std::filesystem;

namespace candela {

namespace {

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

}  // namespace

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
