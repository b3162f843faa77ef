// The pixel filters' table (issue 34: one home per plug-in): each filter's name, dialects,
// parameters and create function. createFilter dispatches through it, and unknown-name errors,
// `candela --list-plugins` and `candela --describe` read it.
#pragma once

#include <memory>
#include <span>

#include "core/plugin_spec.h"
#include "filters/filter.h"

namespace candela {

// What every filter is made from. Bad values are SceneErrors at the parameter or loc; createFilter
// then checks the filter's integral.
using FilterCreate = std::unique_ptr<Filter> (*)(const ParamSet& params, const FileLoc& loc);

struct FilterPlugin {
  PluginSpec spec;
  FilterCreate create;
};

std::span<const FilterPlugin> filterPlugins();

}  // namespace candela
