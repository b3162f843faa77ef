#include "accel/aggregate_factory.h"

#include "accel/accelerator_plugins.h"
#include "core/plugin_spec.h"

namespace candela {

namespace {

// The table's entry for name ("" = the default, the table's first), or its unknown-name error.
const AcceleratorPlugin& requireAccelerator(const std::string& name, const FileLoc& loc) {
  std::string_view wanted = name.empty() ? acceleratorPlugins().front().spec.name : name;
  return requirePlugin(acceleratorPlugins(), "accelerator", std::string(wanted), loc);
}

}  // namespace

const std::vector<std::string>& acceleratorNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (std::string_view n : pluginNames(acceleratorPlugins())) out.emplace_back(n);
    return out;
  }();
  return names;
}

bool isAcceleratorName(const std::string& name) {
  return findPlugin(acceleratorPlugins(), name) != nullptr;
}

std::unique_ptr<Aggregate> createAggregate(const std::string& name, const ParamSet& params,
                                           const SceneGeometry& geometry,
                                           const EmbreeDevice& device, const FileLoc& loc) {
  return requireAccelerator(name, loc).create({&geometry, nullptr, device}, params, loc);
}

std::unique_ptr<Aggregate> createAggregate(const std::string& name, const ParamSet& params,
                                           const std::vector<Primitive>& primitives,
                                           const EmbreeDevice& device, const FileLoc& loc) {
  return requireAccelerator(name, loc).create({nullptr, &primitives, device}, params, loc);
}

}  // namespace candela
