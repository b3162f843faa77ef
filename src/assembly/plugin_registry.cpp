#include "assembly/plugin_registry.h"

#include <algorithm>

#include "accel/accelerator_plugins.h"
#include "cameras/camera_plugins.h"
#include "film/film_plugins.h"
#include "filters/filter_plugins.h"
#include "integrators/integrator_plugins.h"
#include "lights/light_plugins.h"
#include "materials/material_plugins.h"
#include "media/medium_plugins.h"
#include "samplers/sampler_plugins.h"
#include "shapes/shape_plugins.h"
#include "textures/bump_map_plugins.h"
#include "textures/texture_plugins.h"
#include "transport/volume_integrator_plugins.h"

namespace candela {

namespace {

template <class Entry>
PluginKind kindOf(std::string_view kind, std::string_view statement, std::span<const Entry> table) {
  PluginKind k{kind, statement, {}};
  for (const Entry& e : table) k.plugins.push_back(&e.spec);
  return k;
}

}  // namespace

std::vector<PluginKind> pluginKinds() {
  return {
      kindOf("camera", "Camera", cameraPlugins()),
      kindOf("sampler", "Sampler", samplerPlugins()),
      kindOf("filter", "PixelFilter", filterPlugins()),
      kindOf("film", "Film", filmPlugins()),
      kindOf("accelerator", "Accelerator", acceleratorPlugins()),
      kindOf("integrator", "SurfaceIntegrator (pbrt-v2), Integrator (pbrt-v3)",
             integratorPlugins()),
      kindOf("volume integrator", "VolumeIntegrator", volumeIntegratorPlugins()),
      kindOf("renderer", "Renderer", rendererPlugins()),
      kindOf("shape", "Shape", shapePlugins()),
      kindOf("material", "Material, MakeNamedMaterial \"string type\"", materialPlugins()),
      kindOf("bump map", "BumpMap (lrt)", bumpMapPlugins()),
      kindOf("texture", "Texture", texturePlugins()),
      kindOf("light", "LightSource", lightPlugins()),
      kindOf("area light", "AreaLightSource", areaLightPlugins()),
      kindOf("volume region", "Volume (pbrt-v2)", volumeRegionPlugins()),
      kindOf("medium", "MakeNamedMedium \"string type\" (pbrt-v3)", mediumPlugins()),
  };
}

std::string listPlugins(const std::string& kind) {
  std::string out;
  for (const PluginKind& k : pluginKinds()) {
    if (!kind.empty() && k.kind != kind) continue;
    out += std::string(k.kind) + " (" + std::string(k.statement) + "):\n";
    size_t width = 0;
    for (const PluginSpec* p : k.plugins) width = std::max(width, p->name.size());
    for (const PluginSpec* p : k.plugins)
      out += "  " + std::string(p->name) + std::string(width + 2 - p->name.size(), ' ') +
             std::string(p->summary) + " [" + dialectNames(p->dialects) + "]\n";
  }
  return out;
}

std::string describePlugins(const std::string& name) {
  std::string kind, plugin = name;
  if (size_t slash = name.find('/'); slash != std::string::npos) {
    kind = name.substr(0, slash);
    plugin = name.substr(slash + 1);
  }
  std::string out;
  for (const PluginKind& k : pluginKinds())
    for (const PluginSpec* p : k.plugins)
      if (p->name == plugin && (kind.empty() || k.kind == kind)) {
        if (!out.empty()) out += "\n";
        out += describePlugin(*p);
      }
  return out;
}

}  // namespace candela
