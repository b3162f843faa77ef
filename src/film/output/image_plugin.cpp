#include "film/output/image_plugin.h"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "core/error.h"

namespace candela {

namespace fs = std::filesystem;

namespace {

constexpr const char* kPluginFile = "candela_oiio.so";
constexpr const char* kWhatFor =
    "the image plug-in (OpenImageIO), which reads image textures other than OpenEXR and writes "
    "previews";

const ImageCodec& load() {
  const std::vector<std::string> candidates = imagePluginCandidates();
  std::error_code ec;
  for (const std::string& path : candidates) {
    if (!fs::exists(path, ec)) continue;
    // Lazy binding, as the dynamic linker binds libraries linked in: RTLD_NOW would resolve
    // every function of the ~250 libraries up front, 10% more start-up for a preview.
    void* library = ::dlopen(path.c_str(), RTLD_LAZY | RTLD_LOCAL);
    if (!library)
      throw FileError(path, std::string("cannot load ") + kWhatFor + ": " + ::dlerror());
    using Entry = const ImageCodec* (*)(int);
    auto entry = reinterpret_cast<Entry>(::dlsym(library, "candela_image_codec"));
    if (!entry) throw FileError(path, std::string("not a candela image plug-in: ") + ::dlerror());
    const ImageCodec* codec = entry(kImageCodecVersion);
    if (!codec) throw FileError(path, "the image plug-in was built for another version of candela");
    // The library stays loaded for the life of the process: the codec lives in it.
    return *codec;
  }
  std::string also;
  for (size_t i = 1; i < candidates.size(); ++i)
    also += (i == 1 ? " (nor at '" : "', '") + candidates[i];
  if (!also.empty()) also += "')";
  throw FileError(candidates.front(), std::string("not found") + also + ": " + kWhatFor +
                                          "; build the target candela_oiio, or set "
                                          "CANDELA_OIIO_PLUGIN to its path");
}

}  // namespace

std::vector<std::string> imagePluginCandidates() {
  if (const char* env = std::getenv("CANDELA_OIIO_PLUGIN"); env && *env) return {env};
  std::vector<std::string> paths;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) paths.push_back((exe.parent_path() / kPluginFile).string());
#ifdef CANDELA_OIIO_PLUGIN_BUILD_PATH
  if (paths.empty() || paths.front() != CANDELA_OIIO_PLUGIN_BUILD_PATH)
    paths.push_back(CANDELA_OIIO_PLUGIN_BUILD_PATH);
#endif
  if (paths.empty()) paths.push_back(kPluginFile);
  return paths;
}

const ImageCodec& imagePlugin() {
  static const ImageCodec& codec = load();
  return codec;
}

}  // namespace candela
