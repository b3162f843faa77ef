// PixelFilter "name" -> Filter through the filters' table (filters/filter_plugins.cpp: pbrt-v2's
// parameter names and defaults, lrt draft App. C), then the check every filter shares.
#include <cmath>

#include "filters/filter.h"
#include "filters/filter_plugins.h"

namespace candela {

namespace {

// Parameters that are each finite can still make f overflow (mitchell with B = 1e38 and C = -1e38
// gave a NaN in every pixel): the filter must have a finite, positive integral.
std::unique_ptr<Filter> checked(std::unique_ptr<Filter> filter, const std::string& name,
                                const FileLoc& loc) {
  Float integral = filter->integral();
  if (!std::isfinite(integral) || !(integral > 0))
    throw SceneError(loc, name + " filter: these parameters make a filter whose integral is " +
                              std::to_string(integral) + ", not a finite positive number");
  return filter;
}

}  // namespace

std::unique_ptr<Filter> createFilter(const std::string& name, const ParamSet& params,
                                     const FileLoc& loc) {
  const FilterPlugin& plugin = requirePlugin(filterPlugins(), "filter", name, loc);
  return checked(plugin.create(params, loc), name, loc);
}

}  // namespace candela
