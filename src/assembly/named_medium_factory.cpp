#include "assembly/named_medium_factory.h"

#include "media/medium_plugins.h"

namespace candela {

// The media themselves, their parameters and their names are the table of
// media/medium_plugins.cpp.
std::unique_ptr<Medium> createNamedMedium(const MediumDesc& d) {
  std::span<const MediumPlugin> media = mediumPlugins();
  if (const MediumPlugin* plugin = findPlugin(media, d.name))
    return plugin->create({d.params, d.loc, d.mediumToWorld});
  // At the "type" parameter that named it, asked for only on this path: building a known medium
  // asks for no parameter its table does not declare.
  throwUnknownPlugin(d.params.locationOf("type", d.loc), "medium", d.name, pluginNames(media));
}

}  // namespace candela
