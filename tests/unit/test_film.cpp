// The film: crop-window pixel bounds (the lrt draft's ceil rule), crops tiling the image exactly,
// weighted accumulation, the RGBA image it hands to the writers, pbrt-v3's scale and per-sample
// luminance clamp, and the factory.
#include <gtest/gtest.h>

#include <vector>

#include "film/film.h"
#include "filters/box_filter.h"
#include "filters/mitchell_filter.h"
#include "support/param_items.h"

namespace candela {
namespace {

std::unique_ptr<Filter> box() { return std::make_unique<BoxFilter>(Vector2f(0.5f, 0.5f)); }

Bounds2f crop(Float x0, Float x1, Float y0, Float y1) {
  return Bounds2f(Point2f(x0, y0), Point2f(x1, y1));
}

TEST(Film, CropWindowPixelBoundsFollowTheCeilRule) {
  Film full(Point2i(640, 480), crop(0, 1, 0, 1), box(), "a.exr");
  EXPECT_EQ(full.pixelBounds(), Bounds2i(Point2i(0, 0), Point2i(640, 480)));
  Film part(Point2i(640, 480), crop(0.25f, 0.75f, 0.1f, 0.9f), box(), "a.exr");
  EXPECT_EQ(part.pixelBounds(), Bounds2i(Point2i(160, 48), Point2i(480, 432)));
  // 10 x 0.15 = 1.5 -> 2; 10 x 0.55 = 5.5 -> 6; 7 x 0.3 = 2.1 -> 3; 7 x 0.6 = 4.2 -> 5.
  Film frac(Point2i(10, 7), crop(0.15f, 0.55f, 0.3f, 0.6f), box(), "a.exr");
  EXPECT_EQ(frac.pixelBounds(), Bounds2i(Point2i(2, 3), Point2i(6, 5)));
}

TEST(Film, CropWindowIsClampedAndOrdered) {
  Film f(Point2i(100, 50), crop(-0.5f, 2, 0.8f, 0.2f), box(), "a.exr");
  EXPECT_EQ(f.cropWindow().pMin.x, 0.f);
  EXPECT_EQ(f.cropWindow().pMax.x, 1.f);
  EXPECT_EQ(f.cropWindow().pMin.y, 0.2f);
  EXPECT_EQ(f.cropWindow().pMax.y, 0.8f);
  EXPECT_EQ(f.pixelBounds(), Bounds2i(Point2i(0, 10), Point2i(100, 40)));
}

TEST(Film, CropTilesPartitionTheImage) {
  struct Res {
    int x, y, nx, ny;
  };
  for (Res r : {Res{97, 61, 3, 7}, Res{640, 480, 5, 3}, Res{13, 1000, 10, 9}, Res{5, 3, 7, 4}}) {
    std::vector<int> covered(size_t(r.x) * r.y, 0);
    for (int j = 0; j < r.ny; ++j)
      for (int i = 0; i < r.nx; ++i) {
        Film f(Point2i(r.x, r.y),
               crop(Float(i) / r.nx, Float(i + 1) / r.nx, Float(j) / r.ny, Float(j + 1) / r.ny),
               box(), "t.exr");
        const Bounds2i& b = f.pixelBounds();
        for (int y = b.pMin.y; y < b.pMax.y; ++y)
          for (int x = b.pMin.x; x < b.pMax.x; ++x) ++covered[size_t(y) * r.x + x];
      }
    for (size_t k = 0; k < covered.size(); ++k)
      ASSERT_EQ(covered[k], 1) << r.x << "x" << r.y << " pixel " << k;
  }
}

TEST(Film, WeightedMeanAndImageLayout) {
  Film f(Point2i(8, 6), crop(0.25f, 0.75f, 0.5f, 1), box(), "img.exr");
  const Bounds2i& b = f.pixelBounds();
  ASSERT_EQ(b, Bounds2i(Point2i(2, 3), Point2i(6, 6)));
  f.addSample(Point2i(2, 3), Spectrum(1, 2, 3), 1, 1);
  f.addSample(Point2i(2, 3), Spectrum(3, 2, 1), 0, 3);
  f.addSample(Point2i(5, 5), Spectrum(0.5f, 0.25f, 4), 1, 0.5f);
  f.addSample(Point2i(0, 0), Spectrum(100), 1, 1);  // outside the crop: ignored
  Spectrum v = f.pixelValue(Point2i(2, 3));
  EXPECT_FLOAT_EQ(v[0], (1 + 9) / 4.f);
  EXPECT_FLOAT_EQ(v[1], 2.f);
  EXPECT_FLOAT_EQ(v[2], (3 + 3) / 4.f);
  EXPECT_FLOAT_EQ(f.pixelAlpha(Point2i(2, 3)), 0.25f);
  EXPECT_EQ(f.pixelValue(Point2i(3, 3)), Spectrum(0));  // no samples: black

  ImageBuffer img = f.image();
  ASSERT_TRUE(img.consistent());
  EXPECT_EQ(img.width, 4);
  EXPECT_EQ(img.height, 3);
  EXPECT_EQ(img.channels, (std::vector<std::string>{"R", "G", "B", "A"}));
  EXPECT_EQ(img.xOffset, 2);
  EXPECT_EQ(img.yOffset, 3);
  EXPECT_EQ(img.fullWidth, 8);
  EXPECT_EQ(img.fullHeight, 6);
  EXPECT_FLOAT_EQ(img.at(0, 0, 0), 2.5f);  // top-left of the crop: pixel (2, 3)
  EXPECT_FLOAT_EQ(img.at(0, 0, 3), 0.25f);
  EXPECT_FLOAT_EQ(img.at(3, 2, 2), 4.f);  // bottom-right: pixel (5, 5)
  EXPECT_FLOAT_EQ(img.at(3, 2, 3), 1.f);
  EXPECT_EQ(img.at(1, 1, 0), 0.f);
}

TEST(Film, NegativeFilterWeightsStillAverage) {
  Film f(Point2i(2, 2), crop(0, 1, 0, 1),
         std::make_unique<MitchellFilter>(Vector2f(2, 2), 1.f / 3, 1.f / 3), "m.exr");
  f.addSample(Point2i(1, 1), Spectrum(2), 1, 1.2f);
  f.addSample(Point2i(1, 1), Spectrum(1), 1, -0.2f);
  EXPECT_NEAR(f.pixelValue(Point2i(1, 1))[0], (2.4 - 0.2) / 1.0, 1e-6);
}

TEST(FilmFactory, DefaultsAndExplicitValues) {
  FileLoc loc{"f.pbrt", 1, 1};
  auto f = createFilm("image", ParamSet(), box(), loc, std::nullopt);
  EXPECT_EQ(f->fullResolution(), Point2i(640, 480));
  EXPECT_EQ(f->pixelBounds(), Bounds2i(Point2i(0, 0), Point2i(640, 480)));
  EXPECT_EQ(f->filename(), "candela.exr");

  ParamSet ps = test::paramSet({test::ints("xresolution", {32}), test::ints("yresolution", {16}),
                                test::floats("cropwindow", {0.5f, 1, 0, 0.5f}),
                                test::strings("filename", {"out.tiff"})});
  f = createFilm("image", ps, box(), loc, std::nullopt);
  EXPECT_EQ(f->fullResolution(), Point2i(32, 16));
  EXPECT_EQ(f->pixelBounds(), Bounds2i(Point2i(16, 0), Point2i(32, 8)));
  EXPECT_EQ(f->filename(), "out.tiff");  // kept as written
  // The command line's crop window wins over the scene's.
  f = createFilm("image", ps, box(), loc, crop(0, 0.25f, 0.5f, 1));
  EXPECT_EQ(f->pixelBounds(), Bounds2i(Point2i(0, 8), Point2i(8, 16)));
}

TEST(FilmFactory, Errors) {
  FileLoc loc{"f.pbrt", 2, 1};
  EXPECT_THROW(createFilm("rgb", ParamSet(), box(), loc, std::nullopt), SceneError);
  ParamSet bad;
  bad.add(test::floats("cropwindow", {0.5f, 0.5f, 0, 1}, FileLoc{"film.pbrt", 6, 4}));  // no column
  try {
    createFilm("image", bad, box(), loc, std::nullopt);
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(e.location().line, 6) << e.what();
  }
  ParamSet three;
  three.add(test::floats("cropwindow", {0, 1, 0}));
  EXPECT_THROW(createFilm("image", three, box(), loc, std::nullopt), SceneError);
  ParamSet res;
  res.add(test::ints("xresolution", {0}));
  EXPECT_THROW(createFilm("image", res, box(), loc, std::nullopt), SceneError);
}

TEST(Film, ScaleMultipliesEveryPixelValue) {
  // pbrt-v3's "scale" multiplies the written image: the samples' mean, the splats and (squared)
  // the variance.
  auto make = [](Float scale) {
    auto f = std::make_unique<Film>(Point2i(2, 1), crop(0, 1, 0, 1), box(), "s.exr");
    f->setScale(scale);
    f->addSample(Point2i(0, 0), Spectrum(1, 2, 3), 1, 1);
    f->addSample(Point2i(0, 0), Spectrum(3, 2, 1), 1, 1);
    f->enableSplats().add(Point2f(1.5f, 0.5f), Spectrum(0.25f));
    f->addLightPaths(2);
    return f;
  };
  auto plain = make(1), scaled = make(1.5f);
  for (int x = 0; x < 2; ++x)
    for (int c = 0; c < 3; ++c) {
      Point2i p(x, 0);
      EXPECT_FLOAT_EQ(scaled->pixelValue(p)[c], 1.5f * plain->pixelValue(p)[c]) << x << c;
      EXPECT_FLOAT_EQ(scaled->image().at(x, 0, c), 1.5f * plain->image().at(x, 0, c));
      EXPECT_FLOAT_EQ(scaled->pixelVariance(p)[c], 2.25f * plain->pixelVariance(p)[c]);
    }
  EXPECT_GT(plain->pixelValue(Point2i(1, 0))[0], 0);  // the splat arrived
  EXPECT_GT(plain->pixelVariance(Point2i(0, 0))[0], 0);
}

TEST(Film, MaxSampleLuminanceClampsEachSampleKeepingItsColour) {
  Film f(Point2i(2, 2), crop(0, 1, 0, 1), box(), "c.exr");
  f.setMaxSampleLuminance(1);
  // Y = 7.1516 > 1: scaled by 1 / 7.1516, so its Y becomes 1; Y = 0.425 is kept.
  f.addSample(Point2i(0, 0), Spectrum(0, 10, 0), 1, 1);
  f.addSample(Point2i(0, 0), Spectrum(2, 0, 0), 1, 1);
  Spectrum v = f.pixelValue(Point2i(0, 0));
  EXPECT_FLOAT_EQ(v[0], 1.f);
  EXPECT_NEAR(v[1], 0.5 / 0.715160, 1e-6);
  EXPECT_EQ(v[2], 0.f);
  // Splats are clamped too (before the filter spreads them); a pixel set whole (SPPM) is not.
  SplatBuffer& splats = f.enableSplats();
  splats.add(Point2f(1.5f, 0.5f), Spectrum(20));
  EXPECT_NEAR(splats.sum(Point2i(1, 0)).y(), 1, 1e-5);
  f.setPixel(Point2i(0, 1), Spectrum(5), 1);
  EXPECT_FLOAT_EQ(f.pixelValue(Point2i(0, 1))[1], 5.f);
}

TEST(FilmFactory, PbrtV3Parameters) {
  FileLoc loc{"f.pbrt", 1, 1};
  auto f = createFilm("image", ParamSet(), box(), loc, std::nullopt);
  EXPECT_EQ(f->scale(), 1);
  EXPECT_EQ(f->maxSampleLuminance(), kInfinity);
  EXPECT_EQ(f->diagonal(), 35);
  ParamSet ps =
      test::paramSet({test::floats("scale", {1.5f}), test::floats("maxsampleluminance", {10}),
                      test::floats("diagonal", {43.3f})});
  f = createFilm("image", ps, box(), loc, std::nullopt);
  EXPECT_EQ(f->scale(), 1.5f);
  EXPECT_EQ(f->maxSampleLuminance(), 10);
  EXPECT_EQ(f->diagonal(), 43.3f);
  int unused = 0;
  ps.forEachUnused([&](const ParamItem&) { ++unused; });
  EXPECT_EQ(unused, 0);
  // Each must be positive (and finite, but for the clamp): an error at the parameter.
  for (const char* name : {"scale", "maxsampleluminance", "diagonal"})
    for (Float bad : {Float(0), Float(-1), std::numeric_limits<Float>::quiet_NaN()}) {
      ParamSet b;
      b.add(test::floats(name, {bad}, FileLoc{"film.pbrt", 9, 3}));
      try {
        createFilm("image", b, box(), loc, std::nullopt);
        ADD_FAILURE() << name << " " << bad;
      } catch (const SceneError& e) {
        EXPECT_EQ(e.location().line, 9) << e.what();
        EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
      }
    }
  ParamSet infiniteScale;
  infiniteScale.add(test::floats("scale", {kInfinity}));
  EXPECT_THROW(createFilm("image", infiniteScale, box(), loc, std::nullopt), SceneError);
}

}  // namespace
}  // namespace candela
