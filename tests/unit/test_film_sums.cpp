// A film's per-pixel sums through image channels (--sample-range pieces): samples split between
// films and added back give the single film's pixels within the stated bound (1 ulp of float),
// including negative filter weights; the sums themselves survive to 2^-48.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "film/film.h"
#include "film/film_sums.h"
#include "filters/box_filter.h"

namespace candela {
namespace {

std::unique_ptr<Filter> box() { return std::make_unique<BoxFilter>(Vector2f(0.5f, 0.5f)); }

Film makeFilm(const Point2i& res, const Bounds2i& pixels) {
  const Float x0 = Float(pixels.pMin.x) / Float(res.x), y0 = Float(pixels.pMin.y) / Float(res.y);
  const Float x1 = Float(pixels.pMax.x) / Float(res.x), y1 = Float(pixels.pMax.y) / Float(res.y);
  Film film(res, Bounds2f(Point2f(x0, y0), Point2f(x1, y1)), box(), "a.exr");
  film.enableAovs(kAovVariance | kAovSamples);
  return film;
}

int64_t ulps(float a, float b) {
  int32_t ia, ib;
  std::memcpy(&ia, &a, 4);
  std::memcpy(&ib, &b, 4);
  auto ordered = [](int32_t i) { return i < 0 ? int64_t(INT32_MIN) - i : int64_t(i); };
  return std::llabs(ordered(ia) - ordered(ib));
}

TEST(FilmSums, SplitSamplesAddBackToTheSingleFilm) {
  const Point2i res(8, 6);
  const Bounds2i all(Point2i(0, 0), res);
  Film single = makeFilm(res, all), first = makeFilm(res, all), second = makeFilm(res, all);
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> radiance(0, 50), unit(0, 1);
  const int spp = 37, split = 12;
  for (int y = 0; y < res.y; ++y)
    for (int x = 0; x < res.x; ++x)
      for (int s = 0; s < spp; ++s) {
        // Weights of both signs, as a Mitchell filter's importance sampling gives.
        const Float w = unit(rng) < 0.1f ? -1.3f : 1.3f;
        const Spectrum L(radiance(rng), radiance(rng) * unit(rng), 0.01f * radiance(rng));
        const Float alpha = unit(rng) < 0.5f ? 1.f : 0.f;
        single.addSample(Point2i(x, y), L, alpha, w);
        (s < split ? first : second).addSample(Point2i(x, y), L, alpha, w);
      }
  Film merged = makeFilm(res, all);
  for (const Film* piece : {&first, &second}) {
    ImageBuffer image = piece->image();
    appendFilmSums(*piece, image);
    addFilmSums(image, merged);
  }
  const ImageBuffer a = single.image(), b = merged.image();
  ASSERT_EQ(a.channels, b.channels);
  int64_t worst = 0;
  for (size_t i = 0; i < a.data.size(); ++i) worst = std::max(worst, ulps(a.data[i], b.data[i]));
  EXPECT_LE(worst, 1);
  for (int y = 0; y < res.y; ++y)
    for (int x = 0; x < res.x; ++x) EXPECT_EQ(merged.pixelSampleCount(Point2i(x, y)), spp);
}

TEST(FilmSums, KeepTheDoubleSumsTo2ToTheMinus48) {
  const Point2i res(1, 1);
  Film film = makeFilm(res, Bounds2i(Point2i(0, 0), res));
  // A sum far from any float: 1 + 2^-30 has no float within 2^-24 of it.
  film.addSample(Point2i(0, 0), Spectrum(1.f, 3e-9f, 1e15f), 1, 1);
  film.addSample(Point2i(0, 0), Spectrum(1e-9f, 1.f, 1.f), 1, 1);
  ImageBuffer image = film.image();
  appendFilmSums(film, image);
  Film copy = makeFilm(res, Bounds2i(Point2i(0, 0), res));
  addFilmSums(image, copy);
  const Film::PixelSums a = film.pixelSums(Point2i(0, 0)), b = copy.pixelSums(Point2i(0, 0));
  for (int c = 0; c < 3; ++c)
    EXPECT_LE(std::abs(a.rgbSum[c] - b.rgbSum[c]), std::ldexp(std::abs(a.rgbSum[c]), -48)) << c;
  EXPECT_EQ(a.count, b.count);
  EXPECT_EQ(a.weightSum, b.weightSum);
}

TEST(FilmSums, RefuseImagesWithoutSumsOrOutsideTheFilm) {
  const Point2i res(4, 4);
  Film film = makeFilm(res, Bounds2i(Point2i(0, 0), Point2i(2, 2)));
  film.addSample(Point2i(0, 0), Spectrum(1), 1, 1);
  ImageBuffer plain = film.image();
  EXPECT_THROW(addFilmSums(plain, film), std::invalid_argument);
  ImageBuffer withSums = plain;
  appendFilmSums(film, withSums);
  withSums.xOffset = 3;  // reaches x = 4, outside
  Film other = makeFilm(res, Bounds2i(Point2i(0, 0), Point2i(4, 4)));
  EXPECT_THROW(addFilmSums(withSums, other), std::invalid_argument);
  EXPECT_THROW(appendFilmSums(other, plain), std::invalid_argument);  // not other's bounds
  // w^2 L^2 of L = 1e20 is past the float range: refused rather than stored as infinity.
  film.addSample(Point2i(1, 1), Spectrum(1e20f), 1, 1);
  ImageBuffer huge = film.image();
  EXPECT_THROW(appendFilmSums(film, huge), std::invalid_argument);
}

}  // namespace
}  // namespace candela
