#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string_view>

#include "parser/parser.h"
#include "parser/scene_builder.h"
#include "parser/tokenizer.h"
#include "support/scene_error_of.h"

using namespace candela;

namespace {

struct Built {
  std::vector<SceneDescription> frames;
  std::vector<std::string> warnings;
};

Built build(const std::string& text) {
  Built b;
  SceneBuilder builder([&](SceneDescription&& d) { b.frames.push_back(std::move(d)); },
                       [&](const FileLoc& loc, const std::string& msg) {
                         b.warnings.push_back(loc.str() + ": " + msg);
                       });
  parseString(text, "s.pbrt", builder);
  builder.endOfInput(FileLoc{"s.pbrt", 0, 0});
  return b;
}

SceneDescription one(const std::string& text) {
  Built b = build(text);
  EXPECT_EQ(b.frames.size(), 1u);
  return b.frames.empty() ? SceneDescription() : b.frames[0];
}

std::string errorOf(const std::string& text) {
  return test::sceneErrorOf([&] { build(text); });
}

void expectPoint(const Point3f& p, Float x, Float y, Float z) {
  EXPECT_NEAR(p.x, x, 1e-4);
  EXPECT_NEAR(p.y, y, 1e-4);
  EXPECT_NEAR(p.z, z, 1e-4);
}

}  // namespace

TEST(SceneBuilder, TransformsPostMultiply) {
  // CTM = CTM * T: the last transform written applies to the object first (pbrt).
  SceneDescription d = one("WorldBegin\nTranslate 1 0 0\nScale 2 2 2\nShape \"sphere\"\nWorldEnd");
  ASSERT_EQ(d.shapes.size(), 1u);
  expectPoint(d.shapes[0].objectToWorld.start(Point3f(1, 1, 1)), 3, 2, 2);
  EXPECT_FALSE(d.shapes[0].objectToWorld.isAnimated());
  EXPECT_EQ(d.shapes[0].material, -1);  // no Material: the default
  EXPECT_EQ(d.shapes[0].loc.str(), "s.pbrt:4:1");
}

TEST(SceneBuilder, FileMatricesAreColumnMajor) {
  SceneDescription d =
      one("WorldBegin\nTransform [1 0 0 0  0 1 0 0  0 0 1 0  5 6 7 1]\nShape \"a\"\n"
          "ConcatTransform [2 0 0 0  0 2 0 0  0 0 2 0  0 0 0 1]\nShape \"b\"\nWorldEnd");
  expectPoint(d.shapes[0].objectToWorld.start(Point3f(0, 0, 0)), 5, 6, 7);
  expectPoint(d.shapes[1].objectToWorld.start(Point3f(1, 0, 0)), 7, 6, 7);
}

TEST(SceneBuilder, CameraStoresTheInverseCtmAndNamesCameraSpace) {
  SceneDescription d =
      one("LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 30\n"
          "WorldBegin\nAttributeBegin\nCoordSysTransform \"camera\"\nLightSource \"point\"\n"
          "AttributeEnd\nWorldEnd");
  EXPECT_EQ(d.camera.name, "perspective");
  // The camera sits at the eye: camera-space origin maps to (0, 0, -5).
  expectPoint(d.camera.cameraToWorld.start(Point3f(0, 0, 0)), 0, 0, -5);
  ASSERT_EQ(d.lights.size(), 1u);
  expectPoint(d.lights[0].lightToWorld.start(Point3f(0, 0, 0)), 0, 0, -5);
}

TEST(SceneBuilder, WorldBeginResetsTheCtm) {
  SceneDescription d = one("Translate 5 5 5\nWorldBegin\nShape \"sphere\"\nWorldEnd");
  EXPECT_TRUE(d.shapes[0].objectToWorld.start.isIdentity());
}

TEST(SceneBuilder, NamedCoordinateSystems) {
  SceneDescription d =
      one("WorldBegin\nTranslate 1 2 3\nCoordinateSystem \"here\"\nTranslate 10 0 0\n"
          "CoordSysTransform \"here\"\nShape \"a\"\nCoordSysTransform \"world\"\nShape "
          "\"b\"\nWorldEnd");
  expectPoint(d.shapes[0].objectToWorld.start(Point3f(0, 0, 0)), 1, 2, 3);
  EXPECT_TRUE(d.shapes[1].objectToWorld.start.isIdentity());
}

TEST(SceneBuilder, MotionBlurTransforms) {
  SceneDescription d =
      one("TransformTimes 0.5 2\nWorldBegin\nTranslate 1 0 0\nActiveTransform EndTime\n"
          "Translate 0 1 0\nActiveTransform All\nShape \"sphere\"\nWorldEnd");
  const AnimatedTransformDesc& a = d.shapes[0].objectToWorld;
  EXPECT_TRUE(a.isAnimated());
  expectPoint(a.start(Point3f(0, 0, 0)), 1, 0, 0);
  expectPoint(a.end(Point3f(0, 0, 0)), 1, 1, 0);
  EXPECT_EQ(a.startTime, 0.5f);
  EXPECT_EQ(a.endTime, 2.f);
}

TEST(SceneBuilder, AttributesSaveStateTransformsOnlyTheCtm) {
  SceneDescription d =
      one("WorldBegin\nMaterial \"matte\"\nAttributeBegin\nMaterial \"plastic\"\n"
          "AreaLightSource \"area\" \"color L\" [1 1 1]\nReverseOrientation\nTranslate 1 0 0\n"
          "Shape \"a\"\nAttributeEnd\nTransformBegin\nTranslate 0 1 0\nMaterial \"glass\"\n"
          "TransformEnd\nShape \"b\"\nWorldEnd");
  ASSERT_EQ(d.shapes.size(), 2u);
  const ShapeDesc &a = d.shapes[0], &b = d.shapes[1];
  EXPECT_EQ(d.materials[a.material].name, "plastic");
  ASSERT_TRUE(a.areaLight.has_value());
  EXPECT_EQ(a.areaLight->name, "area");
  EXPECT_TRUE(a.reverseOrientation);
  // After AttributeEnd: no area light, no reversal, CTM back to identity; TransformEnd keeps the
  // material set inside it.
  EXPECT_FALSE(b.areaLight.has_value());
  EXPECT_FALSE(b.reverseOrientation);
  EXPECT_TRUE(b.objectToWorld.start.isIdentity());
  EXPECT_EQ(d.materials[b.material].name, "glass");
}

TEST(SceneBuilder, NamedMaterialsTexturesAndBumpMaps) {
  SceneDescription d =
      one("WorldBegin\nTexture \"c\" \"color\" \"checkerboard\"\nTexture \"f\" \"float\" \"fbm\"\n"
          "MakeNamedMaterial \"shiny\" \"string type\" \"plastic\" \"texture Kd\" \"c\"\n"
          "Material \"matte\"\nBumpMap \"wrinkled\"\nShape \"a\"\nNamedMaterial \"shiny\"\nShape "
          "\"b\"\n"
          "WorldEnd");
  ASSERT_EQ(d.textures.size(), 2u);
  EXPECT_EQ(d.textures[0].type, "spectrum");
  EXPECT_EQ(d.textures[0].textureName, "c");
  EXPECT_EQ(d.textures[0].name, "checkerboard");
  EXPECT_EQ(d.textures[1].type, "float");
  const MaterialDesc& shiny = d.materials[d.namedMaterials.at("shiny")];
  EXPECT_EQ(shiny.name, "plastic");
  EXPECT_EQ(shiny.params.getTexture("Kd"), "c");
  const MaterialDesc& a = d.materials[d.shapes[0].material];
  EXPECT_EQ(a.name, "matte");
  ASSERT_TRUE(a.bumpMap.has_value());
  EXPECT_EQ(a.bumpMap->name, "wrinkled");
  EXPECT_EQ(d.shapes[1].material, d.namedMaterials.at("shiny"));
}

TEST(SceneBuilder, ObjectInstancing) {
  SceneDescription d =
      one("WorldBegin\nObjectBegin \"tree\"\nTranslate 0 1 0\nShape \"cone\"\nShape \"sphere\"\n"
          "ObjectEnd\nShape \"ground\"\nTranslate 5 0 0\nObjectInstance \"tree\"\nWorldEnd");
  ASSERT_EQ(d.instanceDefinitions.size(), 1u);
  EXPECT_EQ(d.instanceDefinitions[0].name, "tree");
  EXPECT_EQ(d.instanceDefinitions[0].shapes.size(), 2u);
  ASSERT_EQ(d.shapes.size(), 1u);  // only the ground; ObjectBegin's Translate ended at ObjectEnd
  EXPECT_TRUE(d.shapes[0].objectToWorld.start.isIdentity());
  ASSERT_EQ(d.instanceUses.size(), 1u);
  expectPoint(d.instanceUses[0].instanceToWorld.start(Point3f(0, 0, 0)), 5, 0, 0);
}

TEST(SceneBuilder, LightsVolumesAndMedia) {
  SceneDescription d =
      one("MakeNamedMedium \"fog\" \"string type\" \"homogeneous\"\nMediumInterface \"\" \"fog\"\n"
          "Camera \"perspective\"\nWorldBegin\nMediumInterface \"fog\" \"\"\nShape \"s\"\n"
          "LightSource \"distant\"\nVolume \"homogeneous\"\nWorldEnd");
  ASSERT_EQ(d.media.size(), 1u);
  EXPECT_EQ(d.media[0].mediumName, "fog");
  EXPECT_EQ(d.media[0].name, "homogeneous");
  EXPECT_EQ(d.camera.medium, "fog");
  EXPECT_EQ(d.shapes[0].insideMedium, "fog");
  EXPECT_EQ(d.shapes[0].outsideMedium, "");
  EXPECT_EQ(d.lights.size(), 1u);
  EXPECT_EQ(d.volumes.size(), 1u);
}

TEST(SceneBuilder, OptionsAreRecorded) {
  SceneDescription d =
      one("SearchPath \"/a:/b\"\nSearchPath \"/c:&\"\nFilm \"image\" \"integer xresolution\" 10\n"
          "Sampler \"random\"\nPixelFilter \"box\"\nAccelerator \"kdtree\"\nSurfaceIntegrator "
          "\"path\"\n"
          "VolumeIntegrator \"single\"\nIntegrator \"volpath\"\nRenderer \"sampler\"\n"
          "ToneMap \"contrast\"\nWorldBegin\nWorldEnd");
  EXPECT_EQ(d.searchPath, (std::vector<std::string>{"/c", "/a", "/b"}));
  EXPECT_EQ(d.film.params.getOneInt("xresolution", 0), 10);
  EXPECT_EQ(d.sampler.name, "random");
  EXPECT_EQ(d.filter.name, "box");
  EXPECT_EQ(d.accelerator.name, "kdtree");
  EXPECT_EQ(d.surfaceIntegrator.name, "path");
  EXPECT_EQ(d.volumeIntegrator.name, "single");
  EXPECT_EQ(d.integrator.name, "volpath");
  EXPECT_EQ(d.renderer.name, "sampler");
  EXPECT_EQ(d.toneMap.name, "contrast");
  EXPECT_EQ(d.camera.name, "");  // not given
  EXPECT_EQ(d.worldEndLoc.str(), "s.pbrt:13:1");
}

TEST(SceneBuilder, SeveralFramesPerFile) {
  Built b = build(
      "Film \"image\"\nWorldBegin\nShape \"a\"\nWorldEnd\nSampler \"random\"\n"
      "WorldBegin\nShape \"b\"\nShape \"c\"\nWorldEnd");
  ASSERT_EQ(b.frames.size(), 2u);
  EXPECT_EQ(b.frames[0].shapes.size(), 1u);
  EXPECT_EQ(b.frames[1].shapes.size(), 2u);
  EXPECT_EQ(b.frames[1].film.name, "image");  // options carry over to the next frame
  EXPECT_EQ(b.frames[1].sampler.name, "random");
}

TEST(SceneBuilder, OpenAttributesAtWorldEndWarnPerLevel) {
  Built b = build("WorldBegin\nAttributeBegin\n  AttributeBegin\nShape \"a\"\nWorldEnd");
  ASSERT_EQ(b.frames.size(), 1u);
  ASSERT_EQ(b.warnings.size(), 2u);
  EXPECT_EQ(b.warnings[0], "s.pbrt:3:3: AttributeBegin is not closed at WorldEnd (s.pbrt:5:1)");
  EXPECT_EQ(b.warnings[1], "s.pbrt:2:1: AttributeBegin is not closed at WorldEnd (s.pbrt:5:1)");
}

// ---- One test per error kind -------------------------------------------------------------------

TEST(SceneBuilderErrors, SingularTransform) {
  EXPECT_EQ(errorOf("WorldBegin\n  Scale 0 1 1"),
            "s.pbrt:2:3: error: invalid transformation: scale by zero is not invertible");
  EXPECT_EQ(errorOf("Transform [0 0 0 0  0 0 0 0  0 0 0 0  0 0 0 0]"),
            "s.pbrt:1:1: error: invalid transformation: singular transformation matrix");
}

TEST(SceneBuilderErrors, DegenerateLookAt) {
  EXPECT_EQ(errorOf("LookAt 0 0 0  0 0 0  0 1 0"),
            "s.pbrt:1:1: error: invalid transformation: LookAt: eye and look point coincide");
}

TEST(SceneBuilderErrors, OverflowingTransform) {
  EXPECT_EQ(errorOf("Scale 1e30 1 1\nScale 1e30 1 1"),
            "s.pbrt:2:1: error: the transformation overflows (infinite or NaN matrix entries)");
}

TEST(SceneBuilderErrors, UnmatchedEnd) {
  EXPECT_EQ(errorOf("WorldBegin\nAttributeEnd"),
            "s.pbrt:2:1: error: 'AttributeEnd' without a matching AttributeBegin");
}

TEST(SceneBuilderErrors, MismatchedEnd) {
  EXPECT_EQ(errorOf("WorldBegin\nTransformBegin\nAttributeEnd"),
            "s.pbrt:3:1: error: 'AttributeEnd' does not match the TransformBegin at s.pbrt:2:1");
}

TEST(SceneBuilderErrors, OptionInsideWorld) {
  EXPECT_EQ(errorOf("WorldBegin\nCamera \"perspective\""),
            "s.pbrt:2:1: error: 'Camera' is a rendering option and must come before WorldBegin "
            "(the world block began at s.pbrt:1:1)");
}

TEST(SceneBuilderErrors, WorldStatementBeforeWorldBegin) {
  EXPECT_EQ(errorOf("Shape \"sphere\""),
            "s.pbrt:1:1: error: 'Shape' is only allowed in the world block, after WorldBegin");
}

TEST(SceneBuilderErrors, NestedWorldBegin) {
  EXPECT_EQ(errorOf("WorldBegin\nWorldBegin"),
            "s.pbrt:2:1: error: 'WorldBegin' inside the world block that began at s.pbrt:1:1 "
            "(missing WorldEnd?)");
}

TEST(SceneBuilderErrors, MissingWorldEnd) {
  EXPECT_EQ(errorOf("WorldBegin\nShape \"sphere\""),
            "s.pbrt: error: end of input inside the world block that began at s.pbrt:1:1: "
            "WorldEnd is missing");
}

TEST(SceneBuilderErrors, UnknownNamedMaterial) {
  EXPECT_EQ(errorOf("WorldBegin\nNamedMaterial \"gold\""),
            "s.pbrt:2:1: error: unknown named material 'gold' (not made by MakeNamedMaterial)");
}

TEST(SceneBuilderErrors, NamedMaterialWithoutType) {
  EXPECT_EQ(errorOf("WorldBegin\nMakeNamedMaterial \"gold\" \"float roughness\" 0.1"),
            "s.pbrt:2:1: error: MakeNamedMaterial 'gold' needs a \"string type\" parameter");
}

TEST(SceneBuilderErrors, BadTextureType) {
  EXPECT_EQ(errorOf("WorldBegin\nTexture \"t\" \"vector\" \"constant\""),
            "s.pbrt:2:1: error: texture type must be \"float\", \"spectrum\" or \"color\", found "
            "\"vector\"");
}

TEST(SceneBuilderErrors, NestedObjectBegin) {
  EXPECT_EQ(errorOf("WorldBegin\nObjectBegin \"a\"\nObjectBegin \"b\""),
            "s.pbrt:3:1: error: ObjectBegin 'b' inside the definition of 'a' (begun at "
            "s.pbrt:2:1): object definitions cannot nest");
}

TEST(SceneBuilderErrors, ObjectEndWithoutBegin) {
  EXPECT_EQ(errorOf("WorldBegin\nObjectEnd"),
            "s.pbrt:2:1: error: 'ObjectEnd' without a matching ObjectBegin");
}

TEST(SceneBuilderErrors, UnknownObjectInstance) {
  EXPECT_EQ(errorOf("WorldBegin\nObjectInstance \"ghost\""),
            "s.pbrt:2:1: error: unknown object 'ghost' (not defined by ObjectBegin)");
}

TEST(SceneBuilderErrors, InstanceInsideDefinition) {
  EXPECT_EQ(errorOf("WorldBegin\nObjectBegin \"a\"\nObjectEnd\nObjectBegin \"b\"\n"
                    "ObjectInstance \"a\""),
            "s.pbrt:5:1: error: ObjectInstance 'a' inside the definition of 'b': instances "
            "cannot be used inside ObjectBegin/ObjectEnd");
}

TEST(SceneBuilderErrors, TransformTimesReversed) {
  EXPECT_EQ(errorOf("TransformTimes 1 0"),
            "s.pbrt:1:1: error: TransformTimes end time 0.000000 is before start time 1.000000");
}

TEST(SceneBuilderErrors, TooDeepNesting) {
  std::string text = "WorldBegin\n";
  for (int i = 0; i < 100001; ++i) text += "AttributeBegin\n";
  EXPECT_EQ(errorOf(text),
            "s.pbrt:100002:1: error: AttributeBegin nested more than 100000 levels deep");
}

// ---- Real scenes and robustness ----------------------------------------------------------------

namespace {

std::string pbrtV2Dir() { return std::string(CANDELA_SHARED_SCENES_DIR) + "/pbrt-v2"; }

}  // namespace

TEST(ExternalPbrtV2Scenes, EveryFileParsesThroughTheBuilder) {
  namespace fs = std::filesystem;
  if (!fs::is_directory(pbrtV2Dir())) GTEST_SKIP() << "shared scenes not found: " << pbrtV2Dir();
  int files = 0;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(pbrtV2Dir())) {
    if (e.path().extension() != ".pbrt") continue;
    ++files;
    SCOPED_TRACE(e.path().string());
    std::vector<SceneDescription> frames;
    std::vector<std::string> warnings;
    SceneBuilder builder(
        [&](SceneDescription&& d) { frames.push_back(std::move(d)); },
        [&](const FileLoc& l, const std::string& m) { warnings.push_back(l.str() + ": " + m); });
    bool fragment = e.path().parent_path() != fs::path(pbrtV2Dir());
    try {
      // geometry/*.pbrt are world-block fragments that the scenes Include.
      if (fragment) builder.worldBegin(FileLoc{"test", 1, 1});
      parseFile(e.path().string(), builder);
      if (fragment) builder.worldEnd(FileLoc{"test", 2, 1});
      builder.endOfInput(FileLoc{e.path().string(), 0, 0});
    } catch (const std::exception& ex) {
      ADD_FAILURE() << ex.what();
      continue;
    }
    ASSERT_EQ(frames.size(), 1u);
    EXPECT_FALSE(frames[0].shapes.empty());
    EXPECT_TRUE(warnings.empty()) << warnings[0];
    if (e.path().filename() == "metal.pbrt") {
      // Gold from spds/metals/Au.k.spd: extinction rises toward the red.
      const MaterialDesc* metal = nullptr;
      for (const MaterialDesc& m : frames[0].materials)
        if (m.name == "metal") metal = &m;
      ASSERT_NE(metal, nullptr);
      Spectrum k = metal->params.getOneSpectrum("k", Spectrum());
      EXPECT_GT(k.r(), k.b());
    }
    if (e.path().filename() == "anim-killeroos-moving.pbrt") {
      bool animated = false;
      for (const ShapeDesc& s : frames[0].shapes) animated |= s.objectToWorld.isAnimated();
      EXPECT_TRUE(animated);
    }
  }
  EXPECT_GE(files, 10);
}

namespace {

// A scene using every kind of statement (as the seeds' examples do) for mutation.
const char* kFuzzBase = R"(# mutation base
LookAt 0 5 50  0 -1 0  0 1 0
Camera "perspective" "float fov" [30]
PixelFilter "mitchell" "float xwidth" [2] "float ywidth" [2]
Sampler "bestcandidate"
Film "image" "string filename" ["checkerboard.exr"] "integer xresolution" [300] "integer yresolution" [300]
TransformTimes 0 1
SearchPath "/a:&"
MakeNamedMedium "fog" "string type" "homogeneous" "rgb sigma_a" [.1 .1 .1]
MediumInterface "" "fog"
WorldBegin
LightSource "distant" "point from" [0 10 0] "point to" [0 0 0] "color L" [1 1 1]
LightSource "point" "blackbody I" [5500 1] "spectrum x" [400 1 500 2 600 1]
AttributeBegin
  Rotate 15 0 1 0
  Rotate 100 1 0 0
  Texture "checks" "color" "checkerboard" "float uscale" 4 "color tex1" [1 0 0]
  Material "matte" "texture Kd" "checks" "bool b" "true" "xyz c" [.5 .5 .5]
  BumpMap "wrinkled"
  Shape "disk" "float radius" [100] "float height" [-1]
AttributeEnd
MakeNamedMaterial "gold" "string type" "metal" "float roughness" .01
ObjectBegin "thing"
  NamedMaterial "gold"
  Shape "trianglemesh" "integer indices" [0 1 2] "point P" [0 0 0 1 0 0 0 1 0] "float uv" [0 0 1 0 0 1]
ObjectEnd
TransformBegin
  ActiveTransform EndTime
  Translate 1 2 3
  ActiveTransform All
  ConcatTransform [1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1]
  ObjectInstance "thing"
TransformEnd
AttributeBegin
  AreaLightSource "area" "color L" [4 4 4] "integer nsamples" 4
  ReverseOrientation
  CoordSysTransform "camera"
  Shape "sphere" "float radius" 1
AttributeEnd
Volume "homogeneous" "point p0" [0 0 0] "point p1" [1 1 1]
WorldEnd
)";

const char* kFragments[] = {"[",
                            "]",
                            "\"",
                            "#",
                            "\n",
                            " ",
                            "AttributeBegin\n",
                            "AttributeEnd\n",
                            "WorldBegin\n",
                            "WorldEnd\n",
                            "ObjectBegin \"o\"\n",
                            "ObjectEnd\n",
                            "ObjectInstance \"thing\"\n",
                            "TransformEnd\n",
                            "1e999",
                            "-nan",
                            "nan",
                            "inf",
                            "0",
                            "-1",
                            "3.5",
                            "\"float x\"",
                            "\"spectrum s\" \"/dev/zero\"",
                            "Include \"/dev/zero\"\n",
                            "Include \"fuzz.pbrt\"\n",
                            "Scale 0 0 0\n",
                            "\"blackbody L\" [0 1]",
                            "\\",
                            "\xff\xfe",
                            std::string_view("\0", 1).data(),
                            "Shape",
                            "\"point P\"",
                            "\"integer indices\"",
                            "true",
                            "Option",
                            "MediumInterface",
                            "LookAt 0 0 0 0 0 0 0 0 0\n",
                            "Transform [",
                            "99999999999"};

}  // namespace

TEST(SceneBuilderRobustness, MutatedScenesOnlyEverThrowSceneOrFileErrors) {
  namespace fs = std::filesystem;
  fs::path dir = fs::temp_directory_path() / "candela_fuzz";
  fs::create_directories(dir);
  std::string fuzzFile = (dir / "fuzz.pbrt").string();
  std::ofstream(fuzzFile) << kFuzzBase;

  std::vector<std::string> bases = {kFuzzBase};
  for (const char* name : {"anim-moving-reflection.pbrt", "killeroo-simple.pbrt", "metal.pbrt"}) {
    std::ifstream in(pbrtV2Dir() + "/" + name);
    if (in)
      bases.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }

  std::mt19937 rng(20240607);
  auto uniform = [&](size_t n) { return n == 0 ? size_t(0) : size_t(rng() % n); };
  int accepted = 0, rejected = 0;
  for (int iter = 0; iter < 4000; ++iter) {
    std::string text = bases[uniform(bases.size())];
    int mutations = 1 + int(uniform(4));
    for (int m = 0; m < mutations; ++m) {
      size_t pos = uniform(text.size() + 1);
      switch (uniform(5)) {
        case 0:
          text.resize(pos);
          break;
        case 1:
          text.erase(pos, 1 + uniform(20));
          break;
        case 2: {
          std::string_view f = kFragments[uniform(std::size(kFragments))];
          text.insert(pos, f.empty() ? std::string(1, '\0') : std::string(f));
          break;
        }
        case 3:
          if (pos < text.size()) text[pos] = char(uniform(256));
          break;
        case 4: {
          size_t len = uniform(40);
          text.insert(pos, text.substr(uniform(text.size() + 1), len));
          break;
        }
      }
    }
    int frames = 0;
    SceneBuilder builder([&](SceneDescription&&) { ++frames; },
                         [](const FileLoc&, const std::string&) {});
    try {
      parseString(text, fuzzFile, builder, [](const FileLoc&, const std::string&) {});
      builder.endOfInput(FileLoc{fuzzFile, 0, 0});
      ++accepted;
    } catch (const SceneError&) {
      ++rejected;
    } catch (const FileError&) {
      ++rejected;
    } catch (const std::exception& e) {
      FAIL() << "iteration " << iter << ": unexpected exception: " << e.what() << "\ninput:\n"
             << printable(text, 2000);
    }
  }
  RecordProperty("accepted", accepted);
  RecordProperty("rejected", rejected);
  EXPECT_GT(accepted, 100);
  EXPECT_GT(rejected, 100);
  fs::remove_all(dir);
}

TEST(SceneBuilderRobustness, BinaryGarbageAndHugeInputs) {
  std::mt19937 rng(7);
  for (int i = 0; i < 200; ++i) {
    std::string junk(1 + rng() % 4000, '\0');
    for (char& c : junk) c = char(rng() % 256);
    SceneBuilder builder([](SceneDescription&&) {}, {});
    try {
      parseString(junk, "junk.pbrt", builder);
      builder.endOfInput(FileLoc{"junk.pbrt", 0, 0});
    } catch (const SceneError&) {
    }
  }
  // A long flat array and a long line of brackets do not recurse or blow up.
  std::string many = "WorldBegin\nShape \"trianglemesh\" \"point P\" [";
  for (int i = 0; i < 300000; ++i) many += "1 ";
  many += "]\nWorldEnd\n";
  EXPECT_NO_THROW(build(many));
  EXPECT_THROW(build(std::string(100000, '[')), SceneError);
  EXPECT_THROW(build(std::string(100000, ']')), SceneError);
}

// pbrt-v3: named textures and named materials are graphics state. A statement binds the
// definitions in effect where it is written; AttributeEnd (and ObjectEnd) restores the outer ones.
TEST(SceneBuilder, TexturesAndNamedMaterialsAreScopedByAttributes) {
  Built b = build(
      "WorldBegin\n"
      "Texture \"m\" \"color\" \"constant\" \"rgb value\" [0 0 0]\n"  // 0
      "AttributeBegin\n"
      "Texture \"m\" \"color\" \"constant\" \"rgb value\" [1 0 0]\n"  // 1
      "Material \"matte\" \"texture Kd\" \"m\"\nShape \"sphere\"\n"
      "AttributeEnd\n"
      "AttributeBegin\n"
      "Texture \"m\" \"color\" \"constant\" \"rgb value\" [0 1 0]\n"  // 2
      "Texture \"n\" \"color\" \"scale\" \"texture tex1\" \"m\"\n"    // 3
      "MakeNamedMaterial \"inner\" \"string type\" \"matte\" \"texture Kd\" \"n\"\n"
      "Material \"matte\" \"texture Kd\" \"m\"\nShape \"sphere\"\n"
      "AttributeEnd\n"
      "Material \"matte\" \"texture Kd\" \"m\"\nShape \"trianglemesh\" \"texture alpha\" \"f\"\n"
      "Texture \"f\" \"float\" \"constant\"\n"  // 4
      "Texture \"m\" \"float\" \"constant\"\n"  // 5
      "Material \"matte\" \"texture Kd\" \"m\"\n"
      "WorldEnd");
  ASSERT_EQ(b.frames.size(), 1u);
  const SceneDescription& d = b.frames[0];
  ASSERT_EQ(d.textures.size(), 6u);
  ASSERT_EQ(d.shapes.size(), 3u);
  auto kdOf = [&](const ShapeDesc& s) {
    const MaterialDesc& m = d.materials.at(size_t(s.material));
    EXPECT_TRUE(m.textures.has_value());
    return m.textures->spectra.at("m");
  };
  EXPECT_EQ(kdOf(d.shapes[0]), 1);
  EXPECT_EQ(kdOf(d.shapes[1]), 2);
  EXPECT_EQ(kdOf(d.shapes[2]), 0);  // the blocks' definitions ended with them
  // A texture binds the names it uses at its own statement.
  ASSERT_TRUE(d.textures[3].textures.has_value());
  EXPECT_EQ(d.textures[3].textures->spectra.at("m"), 2);
  // Names defined later are not bound; a float texture of the same name is bound separately.
  ASSERT_TRUE(d.shapes[2].textures.has_value());
  EXPECT_EQ(d.shapes[2].textures->floats.count("f"), 0u);
  const MaterialDesc& last = d.materials.back();
  EXPECT_EQ(last.textures->spectra.at("m"), 0);
  EXPECT_EQ(last.textures->floats.at("m"), 5);
  // The named material made inside the second block is gone after it.
  EXPECT_EQ(d.namedMaterials.count("inner"), 0u);
  // Shadowing inside a block is the normal scoped case: no warning.
  for (const std::string& w : b.warnings) EXPECT_EQ(w.find("redefined"), std::string::npos) << w;
  EXPECT_EQ(errorOf("WorldBegin\nAttributeBegin\nMakeNamedMaterial \"gold\" \"string type\" "
                    "\"metal\"\nAttributeEnd\nNamedMaterial \"gold\"\nWorldEnd"),
            "s.pbrt:5:1: error: unknown named material 'gold' (not made by MakeNamedMaterial)");
}

TEST(SceneBuilder, RedefinitionInTheSameBlockWarns) {
  Built b = build(
      "WorldBegin\nAttributeBegin\nTexture \"m\" \"float\" \"constant\"\n"
      "Texture \"m\" \"float\" \"fbm\"\nMakeNamedMaterial \"g\" \"string type\" \"matte\"\n"
      "MakeNamedMaterial \"g\" \"string type\" \"metal\"\nAttributeEnd\nWorldEnd");
  ASSERT_EQ(b.warnings.size(), 2u);
  EXPECT_EQ(b.warnings[0],
            "s.pbrt:4:1: float texture 'm' redefined in the same attribute block (first defined at "
            "s.pbrt:3:1)");
  EXPECT_EQ(b.warnings[1],
            "s.pbrt:6:1: named material 'g' redefined in the same attribute block (first defined "
            "at s.pbrt:5:1)");
}

// A mix material binds the named materials in effect at its statement.
TEST(SceneBuilder, MixBindsNamedMaterialsWhereWritten) {
  SceneDescription d = one(
      "WorldBegin\nMakeNamedMaterial \"a\" \"string type\" \"matte\"\n"
      "MakeNamedMaterial \"b\" \"string type\" \"mirror\"\n"
      "AttributeBegin\nMakeNamedMaterial \"a\" \"string type\" \"glass\"\n"
      "Material \"mix\" \"string namedmaterial1\" \"a\" \"string namedmaterial2\" \"b\"\n"
      "AttributeEnd\nMaterial \"mix\" \"string namedmaterial1\" \"a\" \"string namedmaterial2\" "
      "\"b\"\nWorldEnd");
  ASSERT_EQ(d.materials.size(), 5u);
  ASSERT_TRUE(d.materials[3].namedMaterials.has_value());
  EXPECT_EQ(d.materials[d.materials[3].namedMaterials->at("a")].name, "glass");
  EXPECT_EQ(d.materials[d.materials[4].namedMaterials->at("a")].name, "matte");
  EXPECT_EQ(d.materials[d.materials[4].namedMaterials->at("b")].name, "mirror");
}
