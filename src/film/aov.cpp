#include "film/aov.h"

#include <sstream>

namespace candela {

namespace {
struct AovName {
  const char* name;
  AovFlag flag;
  std::vector<std::string> channels;
};
const std::vector<AovName>& aovNames() {
  static const std::vector<AovName> names = {
      {"albedo", kAovAlbedo, {"albedo.R", "albedo.G", "albedo.B"}},
      {"normal", kAovNormal, {"N.X", "N.Y", "N.Z"}},
      {"depth", kAovDepth, {"Z"}},
      {"position", kAovPosition, {"P.X", "P.Y", "P.Z"}},
      {"variance", kAovVariance, {"variance.R", "variance.G", "variance.B"}},
      {"samples", kAovSamples, {"samples"}},
  };
  return names;
}
}  // namespace

unsigned parseAovList(const std::string& list, const FileLoc& loc) {
  unsigned flags = 0;
  std::stringstream ss(list);
  std::string item;
  while (std::getline(ss, item, ',')) {
    item.erase(0, item.find_first_not_of(" \t"));
    item.erase(item.find_last_not_of(" \t") + 1);
    if (item.empty()) continue;
    bool found = false;
    for (const auto& a : aovNames())
      if (item == a.name) flags |= a.flag, found = true;
    if (!found) {
      std::string known;
      for (const auto& a : aovNames()) known += (known.empty() ? "" : ", ") + std::string(a.name);
      throw SceneError(loc, "unknown AOV '" + item + "' (known: " + known + ")");
    }
  }
  return flags;
}

std::vector<std::string> aovChannelNames(unsigned flags) {
  std::vector<std::string> out;
  for (const auto& a : aovNames())
    if (flags & a.flag) out.insert(out.end(), a.channels.begin(), a.channels.end());
  return out;
}

}  // namespace candela
