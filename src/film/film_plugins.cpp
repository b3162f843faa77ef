#include "film/film_plugins.h"

#include <algorithm>
#include <cstdint>

namespace candela {

namespace {

std::unique_ptr<Film> createImageFilm(const ParamSet& params, std::unique_ptr<Filter> filter,
                                      const FileLoc& loc, std::optional<Bounds2f> cropOverride) {
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
  // pbrt-v3's film parameters (pbrt 3e §7.9); the luminance clamp may be infinite (no clamp).
  film->setScale(params.getOneFloat("scale", 1, ValueRange::positive(), loc));
  film->setMaxSampleLuminance(
      params.getOneFloat("maxsampleluminance", kInfinity, ValueRange::greaterThan(0), loc));
  film->setDiagonal(params.getOneFloat("diagonal", 35, ValueRange::positive(), loc));
  // candela's output parameters "aovs", "compression" and "half" are read by the render job
  // (assembly/render_job.cpp), which joins them with --aov, --compression and --half; so are
  // adaptive sampling's, checked here.
  params.getOneFloat("noisethreshold", 0, ValueRange::nonNegative(), loc);
  params.getOneInt("adaptiveminsamples", 0, ValueRange::atLeast(0), loc);
  return film;
}

constexpr ParamSpec kImageParams[] = {
    {"xresolution", "integer", "640", "", "within [1, 1048576]", kAllDialects,
     "full image width, pixels"},
    {"yresolution", "integer", "480", "", "within [1, 1048576]", kAllDialects,
     "full image height, pixels"},
    {"cropwindow", "float[]", "0 1 0 1", "", "", kAllDialects,
     "x0 x1 y0 y1 of the image to render, in [0, 1]; must cover a pixel"},
    {"filename", "string", "candela.exr", "", "", kAllDialects,
     "output image, as written (not empty)"},
    {"scale", "float", "1", "", "positive and finite", kPbrtV3, "factor on every pixel value"},
    {"maxsampleluminance", "float", "(infinite)", "", "greater than 0", kPbrtV3,
     "samples brighter than this are scaled down to it"},
    {"diagonal", "float", "35", "", "positive and finite", kPbrtV3,
     "film diagonal in mm (the realistic camera's)"},
    {"aovs", "string", "(none)", "", "", kCandela,
     "comma-separated AOV layers to write (albedo, normal, ...)"},
    {"compression", "string", "zip", "", "", kCandela, "EXR compression (--compression wins)"},
    {"half", "bool", "false", "", "", kCandela, "write half floats (or --half)"},
    {"noisethreshold", "float", "0", "", "non-negative and finite", kCandela,
     "adaptive sampling: a pixel stops once its estimated relative error is at most this (0: "
     "off; or --noise-threshold)"},
    {"adaptiveminsamples", "integer", "0", "", "at least 0", kCandela,
     "adaptive sampling: samples every pixel takes first (0: 16; or --adaptive-min-samples)"},
};

const FilmPlugin kFilms[] = {
    {{"film", "image", kAllDialects,
      "filtered pixel sums written as an EXR image with optional AOV layers (lrt draft §8.1)",
      kImageParams},
     createImageFilm},
};

}  // namespace

std::span<const FilmPlugin> filmPlugins() { return kFilms; }

}  // namespace candela
