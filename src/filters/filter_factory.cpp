// PixelFilter "name" -> Filter, with pbrt-v2's parameter names and defaults (lrt draft App. C:
// xwidth and ywidth are radii; pbrt-v2 defaults them to 0.5 for the box, 4 for the sinc and 2
// otherwise).
#include <cmath>

#include "filters/box_filter.h"
#include "filters/filter.h"
#include "filters/gaussian_filter.h"
#include "filters/mitchell_filter.h"
#include "filters/sinc_filter.h"
#include "filters/triangle_filter.h"

namespace candela {

namespace {

Float positiveParam(const ParamSet& params, const std::string& name, Float def,
                    const FileLoc& loc) {
  Float v = params.getOneFloat(name, def);
  if (!(v > 0) || !std::isfinite(v))
    throw SceneError(params.locationOf(name, loc),
                     "\"" + name + "\" must be a positive number, got " + std::to_string(v));
  return v;
}

Vector2f radiusParam(const ParamSet& params, Float def, const FileLoc& loc) {
  return Vector2f(positiveParam(params, "xwidth", def, loc),
                  positiveParam(params, "ywidth", def, loc));
}

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

std::unique_ptr<Filter> createUncheckedFilter(const std::string& name, const ParamSet& params,
                                              const FileLoc& loc) {
  if (name == "box") return std::make_unique<BoxFilter>(radiusParam(params, 0.5f, loc));
  if (name == "gaussian") {
    Vector2f radius = radiusParam(params, 2, loc);
    return std::make_unique<GaussianFilter>(radius, positiveParam(params, "alpha", 2, loc));
  }
  if (name == "mitchell") {
    Vector2f radius = radiusParam(params, 2, loc);
    Float b = params.getOneFloat("B", 1.f / 3.f), c = params.getOneFloat("C", 1.f / 3.f);
    if (!std::isfinite(b) || !std::isfinite(c))
      throw SceneError(loc, "mitchell filter: \"B\" and \"C\" must be finite");
    return std::make_unique<MitchellFilter>(radius, b, c);
  }
  if (name == "triangle") return std::make_unique<TriangleFilter>(radiusParam(params, 2, loc));
  if (name == "sinc") {
    Vector2f radius = radiusParam(params, 4, loc);
    return std::make_unique<LanczosSincFilter>(radius, positiveParam(params, "tau", 3, loc));
  }
  throw SceneError(loc, "unknown pixel filter \"" + name +
                            "\" (known: box, gaussian, mitchell, triangle, sinc)");
}

}  // namespace

std::unique_ptr<Filter> createFilter(const std::string& name, const ParamSet& params,
                                     const FileLoc& loc) {
  return checked(createUncheckedFilter(name, params, loc), name, loc);
}

}  // namespace candela
