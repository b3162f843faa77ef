#include <gtest/gtest.h>

#include "core/paramset.h"

using namespace candela;

namespace {

ParamItem floats(const std::string& name, ParamType type, std::vector<Float> v, int line = 3) {
  ParamItem item;
  item.type = type;
  item.name = name;
  item.loc = FileLoc{"p.pbrt", line, 9};
  item.floats = std::move(v);
  return item;
}

ParamItem strings(const std::string& name, ParamType type, std::vector<std::string> v) {
  ParamItem item;
  item.type = type;
  item.name = name;
  item.loc = FileLoc{"p.pbrt", 7, 2};
  item.strings = std::move(v);
  return item;
}

template <typename F>
std::string errorOf(F f) {
  try {
    f();
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST(ParamSet, SingleValuesAndDefaults) {
  ParamSet ps;
  ps.add(floats("radius", ParamType::Float, {2.5f}));
  ParamItem n;
  n.type = ParamType::Integer;
  n.name = "nsamples";
  n.ints = {4};
  ps.add(n);
  ParamItem b;
  b.type = ParamType::Bool;
  b.name = "flag";
  b.bools = {true};
  ps.add(b);
  ps.add(strings("filename", ParamType::String, {"a.exr"}));
  ps.add(floats("from", ParamType::Point3, {1, 2, 3}));
  ps.add(floats("dir", ParamType::Vector3, {0, 0, 1}));
  ps.add(floats("n", ParamType::Normal3, {0, 1, 0}));
  ps.add(floats("Kd", ParamType::Spectrum, {.1f, .2f, .3f}));

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
  ps.add(floats("radius", ParamType::Float, {1}));
  ps.add(floats("radius", ParamType::Float, {2}));
  EXPECT_EQ(ps.items().size(), 1u);
  EXPECT_EQ(ps.getOneFloat("radius", 0), 2.f);
}

TEST(ParamSet, TypeMismatchErrorsAtTheItem) {
  ParamSet ps;
  ParamItem item = strings("radius", ParamType::String, {"big"});
  item.typeName = "string";
  ps.add(item);
  EXPECT_EQ(errorOf([&] { ps.getOneFloat("radius", 1); }),
            "p.pbrt:7:2: error: parameter \"string radius\" has type 'string', expected 'float'");
}

TEST(ParamSet, WrongCountErrorsAtTheItem) {
  ParamSet ps;
  ps.add(floats("radius", ParamType::Float, {1, 2}, 5));
  EXPECT_EQ(errorOf([&] { ps.getOneFloat("radius", 1); }),
            "p.pbrt:5:9: error: parameter \"float radius\" needs exactly one value, found 2");
}

TEST(ParamSet, SpectrumOfANonSpectrumItemErrors) {
  ParamSet ps;
  ps.add(floats("Kd", ParamType::Float, {0.5f}, 4));
  EXPECT_EQ(errorOf([&] { ps.getOneSpectrum("Kd", Spectrum()); }),
            "p.pbrt:4:9: error: parameter \"float Kd\" has type 'float', expected 'spectrum'");
}

TEST(ParamSet, Arrays) {
  ParamSet ps;
  ps.add(floats("P", ParamType::Point3, {0, 0, 0, 1, 2, 3}));
  ps.add(floats("N", ParamType::Normal3, {0, 0, 1}));
  ps.add(floats("S", ParamType::Vector3, {1, 0, 0}));
  ps.add(floats("st", ParamType::Point2, {0, 1, 2, 3}));
  ps.add(floats("c", ParamType::Spectrum, {1, 1, 1, 0, 0, 0}));
  ps.add(floats("w", ParamType::Float, {1, 2, 3}));
  ps.add(strings("names", ParamType::String, {"a", "b"}));
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
  ps.add(floats("uv", ParamType::Float, {0, 0, 5, 0, 5, 5, 0, 5}));
  std::vector<Point2f> uv = ps.getPoint2fArray("uv");
  ASSERT_EQ(uv.size(), 4u);
  EXPECT_EQ(uv[2], Point2f(5, 5));
  ps.add(floats("st", ParamType::Float, {0, 0, 5}, 6));
  EXPECT_EQ(errorOf([&] { ps.getPoint2fArray("st"); }),
            "p.pbrt:6:9: error: parameter \"float st\" needs (u, v) pairs: an even count of "
            "numbers, found 3");
}

TEST(ParamSet, ArrayTypeMismatchErrors) {
  ParamSet ps;
  ps.add(floats("P", ParamType::Vector3, {0, 0, 0}, 8));
  EXPECT_EQ(errorOf([&] { ps.getPoint3fArray("P"); }),
            "p.pbrt:8:9: error: parameter \"vector3 P\" has type 'vector3', expected 'point3'");
}

TEST(ParamSet, TextureLookupFallsBackQuietly) {
  ParamSet ps;
  ps.add(strings("Kd", ParamType::Texture, {"checks"}));
  ps.add(floats("Ks", ParamType::Spectrum, {1, 1, 1}));
  EXPECT_EQ(ps.getTexture("Kd"), "checks");
  EXPECT_EQ(ps.getTexture("Ks"), "");  // a constant colour, not a texture: no error
  EXPECT_EQ(ps.getTexture("bumpmap"), "");
  EXPECT_EQ(ps.getOneSpectrum("Ks", Spectrum()), Spectrum(1));
}

TEST(ParamSet, UnusedItemsAreReported) {
  ParamSet ps;
  ps.add(floats("radius", ParamType::Float, {1}));
  ps.add(floats("zmin", ParamType::Float, {1}));
  ps.add(floats("_private", ParamType::Float, {1}));
  ps.getOneFloat("radius", 0);
  std::vector<std::string> unused;
  ps.forEachUnused([&](const ParamItem& i) { unused.push_back(i.name); });
  EXPECT_EQ(unused, std::vector<std::string>{"zmin"});
  EXPECT_EQ(ps.locationOf("zmin", FileLoc{}).str(), "p.pbrt:3:9");
  EXPECT_EQ(ps.locationOf("none", FileLoc{"x", 1, 1}).str(), "x:1:1");
}
