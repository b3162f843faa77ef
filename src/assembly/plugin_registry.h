// Every kind's plug-in table in one place, for `candela --list-plugins` and `--describe` and the
// test that checks the declarations (tests/unit/test_plugin_tables.cpp). The tables themselves
// sit beside their classes; this only lists them, in the order a scene file's statements come.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/plugin_spec.h"

namespace candela {

struct PluginKind {
  std::string_view kind;       // as PluginSpec::kind and errors name it: "shape", "area light"
  std::string_view statement;  // the scene statement that names one: "Shape", "AreaLightSource"
  std::vector<const PluginSpec*> plugins;
};

std::vector<PluginKind> pluginKinds();

// `candela --list-plugins [KIND]`: each kind (or the one named) with its plug-ins' names, dialects
// and summaries. Empty when KIND names no kind.
std::string listPlugins(const std::string& kind = "");
// `candela --describe NAME` (or KIND/NAME): every plug-in of that name; empty when there is none.
std::string describePlugins(const std::string& name);

}  // namespace candela
