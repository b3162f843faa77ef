// Film "name" -> Film through the films' table (film/film_plugins.cpp: pbrt-v2's parameter names
// and defaults, lrt draft App. C), and the frame (resolution and crop window) the film and the
// render job both read. The display-pipeline parameters of the draft's ImageFilm (gamma, tone
// mapping, bloom, ...) belong to output (the ToneMap statement) and are not read here.
#include <cmath>

#include "film/film.h"
#include "film/film_plugins.h"

namespace candela {

namespace {

int resolutionParam(const ParamSet& params, const std::string& name, int def, const FileLoc& loc) {
  return params.getOneInt(name, def, ValueRange::within(1, 1 << 20), loc);
}

Bounds2f cropParam(const ParamSet& params, const FileLoc& loc) {
  std::vector<Float> c = params.getFloatArray("cropwindow");
  if (c.empty()) return Bounds2f(Point2f(0, 0), Point2f(1, 1));
  FileLoc where = params.locationOf("cropwindow", loc);
  if (c.size() != 4)
    throw SceneError(
        where, "\"cropwindow\" needs 4 values (x0 x1 y0 y1), got " + std::to_string(c.size()));
  return Bounds2f(Point2f(c[0], c[2]), Point2f(c[1], c[3]));
}

}  // namespace

FilmFrame filmFrame(const ParamSet& params, const FileLoc& loc,
                    std::optional<Bounds2f> cropOverride) {
  Point2i res(resolutionParam(params, "xresolution", 640, loc),
              resolutionParam(params, "yresolution", 480, loc));
  Bounds2f crop = cropParam(params, loc);
  FileLoc cropLoc = params.locationOf("cropwindow", loc);
  if (cropOverride) {
    crop = *cropOverride;
    cropLoc = loc;
  }
  if (std::isnan(crop.pMin.x + crop.pMin.y + crop.pMax.x + crop.pMax.y))
    throw SceneError(cropLoc, "crop window has a NaN value");
  if (Film::pixelBoundsOf(res, crop).empty())
    throw SceneError(cropLoc, "crop window [" + std::to_string(crop.pMin.x) + " " +
                                  std::to_string(crop.pMax.x) + " " + std::to_string(crop.pMin.y) +
                                  " " + std::to_string(crop.pMax.y) + "] covers no pixel of the " +
                                  std::to_string(res.x) + "x" + std::to_string(res.y) + " image");
  return {res, crop};
}

std::unique_ptr<Film> createFilm(const std::string& name, const ParamSet& params,
                                 std::unique_ptr<Filter> filter, const FileLoc& loc,
                                 std::optional<Bounds2f> cropOverride) {
  const FilmPlugin& plugin = requirePlugin(filmPlugins(), "film", name, loc);
  return plugin.create(params, std::move(filter), loc, cropOverride);
}

}  // namespace candela
