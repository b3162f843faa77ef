#include "core/plugin_spec.h"

#include <algorithm>

namespace candela {

std::string dialectNames(unsigned mask) {
  std::string out;
  auto add = [&](unsigned bit, const char* name) {
    if (mask & bit) out += (out.empty() ? "" : ", ") + std::string(name);
  };
  add(kLrt, "lrt");
  add(kPbrtV2, "pbrt-v2");
  add(kPbrtV3, "pbrt-v3");
  add(kCandela, "candela");
  return out;
}

void throwUnknownPlugin(const FileLoc& loc, std::string_view kind, const std::string& name,
                        const std::vector<std::string_view>& known) {
  std::string list;
  for (std::string_view k : known) list += (list.empty() ? "" : ", ") + std::string(k);
  std::string message = "unknown " + std::string(kind) + " '" + name + "' (known: " + list + ")";
  // Names given outside any file (a command-line option, a library caller) have no location.
  if (loc.file.empty()) throw SceneError(message);
  throw SceneError(loc, message);
}

std::string describePlugin(const PluginSpec& spec) {
  std::string out = std::string(spec.kind) + " \"" + std::string(spec.name) +
                    "\": " + std::string(spec.summary) +
                    "\n  dialects: " + dialectNames(spec.dialects) + "\n";
  if (spec.params.empty()) return out + "  (no parameters)\n";
  size_t width = 0;
  for (const ParamSpec& p : spec.params)
    width = std::max(width, p.type.size() + 1 + p.name.size() + 2);
  for (const ParamSpec& p : spec.params) {
    // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "..." + std::string here.
    std::string head = "\"";
    head.append(p.type).append(" ").append(p.name).append("\"");
    out += "  " + head + std::string(width + 1 - std::min(width, head.size()), ' ');
    out += "default " + std::string(p.defaultValue);
    if (!p.pbrtV3Default.empty()) out += " (pbrt-v3: " + std::string(p.pbrtV3Default) + ")";
    if (!p.rule.empty()) out += "; " + std::string(p.rule);
    if (p.dialects != spec.dialects) out += "; " + dialectNames(p.dialects) + " only";
    if (!p.onlyWhen.empty()) out += "; only " + std::string(p.onlyWhen);
    if (!p.meaning.empty()) out += " -- " + std::string(p.meaning);
    out += "\n";
  }
  return out;
}

}  // namespace candela
