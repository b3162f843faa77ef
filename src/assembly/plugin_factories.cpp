#include "assembly/plugin_factories.h"

namespace candela {

void throwUnknownPlugin(const FileLoc& loc, const std::string& kind, const std::string& name,
                        const std::vector<std::string>& known) {
  std::string list;
  for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
  throw SceneError(loc, "unknown " + kind + " '" + name + "' (known: " + list + ")");
}

}  // namespace candela
