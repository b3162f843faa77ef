// Film "image" -> Film, with pbrt-v2's parameter names and defaults (lrt draft App. C). The
// display-pipeline parameters of the draft's ImageFilm (gamma, tone mapping, bloom, ...) belong
// to output and are not read here.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "film/film.h"

namespace candela {

namespace {

int resolutionParam(const ParamSet& params, const std::string& name, int def, const FileLoc& loc) {
  int v = params.getOneInt(name, def);
  if (v < 1 || v > (1 << 20))
    throw SceneError(params.locationOf(name, loc),
                     "\"" + name + "\" must be between 1 and 2^20, got " + std::to_string(v));
  return v;
}

// A float parameter that must be positive (infinity allowed only when allowInfinite).
Float positiveParam(const ParamSet& params, const std::string& name, Float def, bool allowInfinite,
                    const FileLoc& loc) {
  Float v = params.getOneFloat(name, def);
  if (!(v > 0) || (!allowInfinite && std::isinf(v)))
    throw SceneError(params.locationOf(name, loc), "\"" + name + "\" must be positive" +
                                                       (allowInfinite ? "" : " and finite") +
                                                       ", got " + std::to_string(v));
  return v;
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
  if (name != "image") throw SceneError(loc, "unknown film \"" + name + "\" (known: image)");
  if (!filter) throw SceneError(loc, "film: no pixel filter");
  const auto [res, crop] = filmFrame(params, loc, cropOverride);
  std::string filename = params.getOneString("filename", "candela.exr");
  if (filename.empty()) throw SceneError(params.locationOf("filename", loc), "empty filename");
  // The film keeps about 112 bytes per pixel (sums in double for the mean and the variance): past
  // 2^27 pixels (15 GB) a render would exhaust memory rather than fail clearly.
  constexpr int64_t kMaxPixels = int64_t(1) << 27;
  Bounds2i bounds = Film::pixelBoundsOf(res, crop);
  int64_t pixels = int64_t(std::max(0, bounds.pMax.x - bounds.pMin.x)) *
                   std::max(0, bounds.pMax.y - bounds.pMin.y);
  if (pixels > kMaxPixels)
    throw SceneError(loc, std::string("film: ")
                              .append(std::to_string(pixels))
                              .append(" pixels to render (")
                              .append(std::to_string(res.x))
                              .append("x")
                              .append(std::to_string(res.y))
                              .append(" in the crop window); at most 2^27 = ")
                              .append(std::to_string(kMaxPixels)));
  auto film = std::make_unique<Film>(res, crop, std::move(filter), filename);
  // pbrt-v3's film parameters (pbrt 3e §7.9).
  film->setScale(positiveParam(params, "scale", 1, false, loc));
  film->setMaxSampleLuminance(positiveParam(params, "maxsampleluminance", kInfinity, true, loc));
  film->setDiagonal(positiveParam(params, "diagonal", 35, false, loc));
  return film;
}

}  // namespace candela
