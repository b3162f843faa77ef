#include <gtest/gtest.h>

#include "core/paramset.h"
#include "support/param_items.h"
#include "support/scene_error_of.h"

using namespace candela;

namespace {

using test::sceneErrorOf;

}  // namespace

TEST(ParamSet, SingleValuesAndDefaults) {
  ParamSet ps;
  ps.add(test::floats("radius", {2.5f}));
  ps.add(test::ints("nsamples", {4}));
  ps.add(test::bools("flag", {true}));
  ps.add(test::strings("filename", {"a.exr"}));
  ps.add(test::points("from", {1, 2, 3}));
  ps.add(test::vectors("dir", {0, 0, 1}));
  ps.add(test::normals("n", {0, 1, 0}));
  ps.add(test::rgb("Kd", {.1f, .2f, .3f}));

  EXPECT_EQ(ps.getOneFloat("radius", 1), 2.5f);
  EXPECT_EQ(ps.getOneFloat("absent", 7), 7.f);
  EXPECT_EQ(ps.getOneInt("nsamples", 1), 4);
  EXPECT_TRUE(ps.getOneBool("flag", false));
  EXPECT_EQ(ps.getOneString("filename", ""), "a.exr");
  EXPECT_EQ(ps.getOnePoint3f("from", Point3f()), Point3f(1, 2, 3));
  EXPECT_EQ(ps.getOneVector3f("dir", Vector3f()).z, 1.f);
  EXPECT_EQ(ps.getOneNormal3f("n", Normal3f()).y, 1.f);
  EXPECT_EQ(ps.getOneSpectrum("Kd", Spectrum()), Spectrum(.1f, .2f, .3f));
  EXPECT_EQ(ps.getOneSpectrum("Ks", Spectrum(9)), Spectrum(9));
}

TEST(ParamSet, AddReplacesSameName) {
  ParamSet ps;
  ps.add(test::floats("radius", {1}));
  ps.add(test::floats("radius", {2}));
  EXPECT_EQ(ps.items().size(), 1u);
  EXPECT_EQ(ps.getOneFloat("radius", 0), 2.f);
}

TEST(ParamSet, TypeMismatchErrorsAtTheItem) {
  ParamSet ps;
  ps.add(test::strings("radius", {"big"}, FileLoc{"p.pbrt", 7, 2}));
  EXPECT_EQ(sceneErrorOf([&] { ps.getOneFloat("radius", 1); }),
            "p.pbrt:7:2: error: parameter \"string radius\" has type 'string', expected 'float'");
}

TEST(ParamSet, WrongCountErrorsAtTheItem) {
  ParamSet ps;
  ps.add(test::floats("radius", {1, 2}, FileLoc{"p.pbrt", 5, 9}));
  EXPECT_EQ(sceneErrorOf([&] { ps.getOneFloat("radius", 1); }),
            "p.pbrt:5:9: error: parameter \"float radius\" needs exactly one value, found 2");
}

TEST(ParamSet, SpectrumOfANonSpectrumItemErrors) {
  ParamSet ps;
  ps.add(test::floats("Kd", {0.5f}, FileLoc{"p.pbrt", 4, 9}));
  EXPECT_EQ(sceneErrorOf([&] { ps.getOneSpectrum("Kd", Spectrum()); }),
            "p.pbrt:4:9: error: parameter \"float Kd\" has type 'float', expected 'spectrum'");
}

TEST(ParamSet, Arrays) {
  ParamSet ps;
  ps.add(test::points("P", {0, 0, 0, 1, 2, 3}));
  ps.add(test::normals("N", {0, 0, 1}));
  ps.add(test::vectors("S", {1, 0, 0}));
  ps.add(test::point2s("st", {0, 1, 2, 3}));
  ps.add(test::rgb("c", {1, 1, 1, 0, 0, 0}));
  ps.add(test::floats("w", {1, 2, 3}));
  ps.add(test::strings("names", {"a", "b"}));
  EXPECT_EQ(ps.getPoint3fArray("P").size(), 2u);
  EXPECT_EQ(ps.getPoint3fArray("P")[1], Point3f(1, 2, 3));
  EXPECT_EQ(ps.getNormal3fArray("N").size(), 1u);
  EXPECT_EQ(ps.getVector3fArray("S").size(), 1u);
  EXPECT_EQ(ps.getPoint2fArray("st")[1], Point2f(2, 3));
  EXPECT_EQ(ps.getSpectrumArray("c")[1], Spectrum(0));
  EXPECT_EQ(ps.getFloatArray("w").size(), 3u);
  EXPECT_EQ(ps.getStringArray("names")[1], "b");
  EXPECT_TRUE(ps.getIntArray("indices").empty());
  EXPECT_TRUE(ps.getPoint3fArray("absent").empty());
}

TEST(ParamSet, Point2ArrayFromFloatPairs) {
  // pbrt-v2 meshes: "float uv" [ 0 0 5 0 5 5 0 5 ].
  ParamSet ps;
  ps.add(test::floats("uv", {0, 0, 5, 0, 5, 5, 0, 5}));
  std::vector<Point2f> uv = ps.getPoint2fArray("uv");
  ASSERT_EQ(uv.size(), 4u);
  EXPECT_EQ(uv[2], Point2f(5, 5));
  ps.add(test::floats("st", {0, 0, 5}, FileLoc{"p.pbrt", 6, 9}));
  EXPECT_EQ(sceneErrorOf([&] { ps.getPoint2fArray("st"); }),
            "p.pbrt:6:9: error: parameter \"float st\" needs (u, v) pairs: an even count of "
            "numbers, found 3");
}

TEST(ParamSet, ArrayTypeMismatchErrors) {
  ParamSet ps;
  ps.add(test::vectors("P", {0, 0, 0}, FileLoc{"p.pbrt", 8, 9}));
  EXPECT_EQ(sceneErrorOf([&] { ps.getPoint3fArray("P"); }),
            "p.pbrt:8:9: error: parameter \"vector3 P\" has type 'vector3', expected 'point3'");
}

TEST(ParamSet, TextureLookupFallsBackQuietly) {
  ParamSet ps;
  ps.add(test::texture("Kd", "checks"));
  ps.add(test::rgb("Ks", {1, 1, 1}));
  EXPECT_EQ(ps.getTexture("Kd"), "checks");
  EXPECT_EQ(ps.getTexture("Ks"), "");  // a constant colour, not a texture: no error
  EXPECT_EQ(ps.getTexture("bumpmap"), "");
  EXPECT_EQ(ps.getOneSpectrum("Ks", Spectrum()), Spectrum(1));
}

TEST(ParamSet, UnusedItemsAreReported) {
  ParamSet ps;
  ps.add(test::floats("radius", {1}));
  ps.add(test::floats("zmin", {1}, FileLoc{"p.pbrt", 3, 9}));
  ps.add(test::floats("_private", {1}));
  ps.getOneFloat("radius", 0);
  std::vector<std::string> unused;
  ps.forEachUnused([&](const ParamItem& i) { unused.push_back(i.name); });
  EXPECT_EQ(unused, std::vector<std::string>{"zmin"});
  EXPECT_EQ(ps.locationOf("zmin", FileLoc{}).str(), "p.pbrt:3:9");
  EXPECT_EQ(ps.locationOf("none", FileLoc{"x", 1, 1}).str(), "x:1:1");
}
