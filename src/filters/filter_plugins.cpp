#include "filters/filter_plugins.h"

#include "filters/box_filter.h"
#include "filters/gaussian_filter.h"
#include "filters/mitchell_filter.h"
#include "filters/sinc_filter.h"
#include "filters/triangle_filter.h"

namespace candela {

namespace {

// xwidth and ywidth are radii (lrt draft App. C); pbrt-v2 defaults them to 0.5 for the box, 4 for
// the sinc and 2 otherwise.
Vector2f radiusParam(const ParamSet& params, Float def, const FileLoc& loc) {
  Float x = params.getOneFloat("xwidth", def, ValueRange::positive(), loc);
  Float y = params.getOneFloat("ywidth", def, ValueRange::positive(), loc);
  return Vector2f(x, y);
}

std::unique_ptr<Filter> createBox(const ParamSet& params, const FileLoc& loc) {
  return std::make_unique<BoxFilter>(radiusParam(params, 0.5f, loc));
}

std::unique_ptr<Filter> createGaussian(const ParamSet& params, const FileLoc& loc) {
  Vector2f radius = radiusParam(params, 2, loc);
  return std::make_unique<GaussianFilter>(
      radius, params.getOneFloat("alpha", 2, ValueRange::positive(), loc));
}

std::unique_ptr<Filter> createMitchell(const ParamSet& params, const FileLoc& loc) {
  Vector2f radius = radiusParam(params, 2, loc);
  Float b = params.getOneFloat("B", 1.f / 3.f, ValueRange::finite(), loc);
  Float c = params.getOneFloat("C", 1.f / 3.f, ValueRange::finite(), loc);
  return std::make_unique<MitchellFilter>(radius, b, c);
}

std::unique_ptr<Filter> createTriangle(const ParamSet& params, const FileLoc& loc) {
  return std::make_unique<TriangleFilter>(radiusParam(params, 2, loc));
}

std::unique_ptr<Filter> createSinc(const ParamSet& params, const FileLoc& loc) {
  Vector2f radius = radiusParam(params, 4, loc);
  return std::make_unique<LanczosSincFilter>(
      radius, params.getOneFloat("tau", 3, ValueRange::positive(), loc));
}

constexpr ParamSpec kBoxParams[] = {
    {"xwidth", "float", "0.5", "", "positive and finite", kAllDialects, "radius in x, pixels"},
    {"ywidth", "float", "0.5", "", "positive and finite", kAllDialects, "radius in y, pixels"},
};

constexpr ParamSpec kGaussianParams[] = {
    {"xwidth", "float", "2", "", "positive and finite", kAllDialects, "radius in x, pixels"},
    {"ywidth", "float", "2", "", "positive and finite", kAllDialects, "radius in y, pixels"},
    {"alpha", "float", "2", "", "positive and finite", kAllDialects, "falloff rate"},
};

// 0.33333334 is the float 1/3 the code uses.
constexpr ParamSpec kMitchellParams[] = {
    {"xwidth", "float", "2", "", "positive and finite", kAllDialects, "radius in x, pixels"},
    {"ywidth", "float", "2", "", "positive and finite", kAllDialects, "radius in y, pixels"},
    {"B", "float", "0.33333334", "", "finite", kAllDialects, "Mitchell-Netravali B (1/3)"},
    {"C", "float", "0.33333334", "", "finite", kAllDialects, "Mitchell-Netravali C (1/3)"},
};

constexpr ParamSpec kTriangleParams[] = {
    {"xwidth", "float", "2", "", "positive and finite", kAllDialects, "radius in x, pixels"},
    {"ywidth", "float", "2", "", "positive and finite", kAllDialects, "radius in y, pixels"},
};

constexpr ParamSpec kSincParams[] = {
    {"xwidth", "float", "4", "", "positive and finite", kAllDialects, "radius in x, pixels"},
    {"ywidth", "float", "4", "", "positive and finite", kAllDialects, "radius in y, pixels"},
    {"tau", "float", "3", "", "positive and finite", kAllDialects,
     "sinc periods under the Lanczos window"},
};

const FilterPlugin kFilters[] = {
    {{"filter", "box", kAllDialects, "equal weight over the radius (lrt draft §7.7.1)", kBoxParams},
     createBox},
    {{"filter", "gaussian", kAllDialects,
      "Gaussian less its value at the radius (lrt draft §7.7.3)", kGaussianParams},
     createGaussian},
    {{"filter", "mitchell", kAllDialects,
      "Mitchell-Netravali cubic, B and C free (lrt draft §7.7.4)", kMitchellParams},
     createMitchell},
    {{"filter", "triangle", kAllDialects, "tent falling to 0 at the radius (lrt draft §7.7.2)",
      kTriangleParams},
     createTriangle},
    {{"filter", "sinc", kAllDialects, "Lanczos-windowed sinc (lrt draft §7.7.5)", kSincParams},
     createSinc},
};

}  // namespace

std::span<const FilterPlugin> filterPlugins() { return kFilters; }

}  // namespace candela
