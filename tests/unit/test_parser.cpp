#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "parser/parser.h"
#include "support/scene_error_of.h"

using namespace candela;

namespace {

// Records every call as one line of text ("shape sphere radius" ...) plus the parameter sets.
class Recorder : public ParserTarget {
 public:
  std::vector<std::string> calls;
  std::vector<ParamSet> params;

  void log(const std::string& s, const FileLoc& loc) { calls.push_back(s + " @" + loc.str()); }
  void logNamed(const std::string& what, const std::string& name, ParamSet ps, const FileLoc& loc) {
    log(what + " " + name, loc);
    params.push_back(std::move(ps));
  }
  static std::string nums(std::initializer_list<Float> v) {
    std::ostringstream s;
    for (Float f : v) s << " " << f;
    return s.str();
  }

  void identity(const FileLoc& l) override { log("identity", l); }
  void translate(Float x, Float y, Float z, const FileLoc& l) override {
    log("translate" + nums({x, y, z}), l);
  }
  void scale(Float x, Float y, Float z, const FileLoc& l) override {
    log("scale" + nums({x, y, z}), l);
  }
  void rotate(Float a, Float x, Float y, Float z, const FileLoc& l) override {
    log("rotate" + nums({a, x, y, z}), l);
  }
  void lookAt(Float a, Float b, Float c, Float d, Float e, Float f, Float g, Float h, Float i,
              const FileLoc& l) override {
    log("lookAt" + nums({a, b, c, d, e, f, g, h, i}), l);
  }
  void transform(const Float m[16], const FileLoc& l) override {
    log("transform" + nums({m[0], m[12], m[15]}), l);
  }
  void concatTransform(const Float m[16], const FileLoc& l) override {
    log("concatTransform" + nums({m[0], m[12], m[15]}), l);
  }
  void coordinateSystem(const std::string& n, const FileLoc& l) override {
    log("coordinateSystem " + n, l);
  }
  void coordSysTransform(const std::string& n, const FileLoc& l) override {
    log("coordSysTransform " + n, l);
  }
  void activeTransformAll(const FileLoc& l) override { log("activeAll", l); }
  void activeTransformStartTime(const FileLoc& l) override { log("activeStart", l); }
  void activeTransformEndTime(const FileLoc& l) override { log("activeEnd", l); }
  void transformTimes(Float s, Float e, const FileLoc& l) override {
    log("transformTimes" + nums({s, e}), l);
  }
  void transformBegin(const FileLoc& l) override { log("transformBegin", l); }
  void transformEnd(const FileLoc& l) override { log("transformEnd", l); }
  void reverseOrientation(const FileLoc& l) override { log("reverseOrientation", l); }
  void camera(const std::string& n, ParamSet p, const FileLoc& l) override {
    logNamed("camera", n, std::move(p), l);
  }
  void sampler(const std::string& n, ParamSet p, const FileLoc& l) override {
    logNamed("sampler", n, std::move(p), l);
  }
  void pixelFilter(const std::string& n, ParamSet p, const FileLoc& l) override {
    logNamed("pixelFilter", n, std::move(p), l);
  }
  void film(const std::string& n, ParamSet p, const FileLoc& l) override {
    logNamed("film", n, std::move(p), l);
  }
  void accelerator(const std::string& n, ParamSet p, const FileLoc& l) override {
    logNamed("accelerator", n, std::move(p), l);
  }
  void surfaceIntegrator(const std::string& n, ParamSet p, const FileLoc& l) override {
    logNamed("surfaceIntegrator", n, std::move(p), l);
  }
  void volumeIntegrator(const std::string& n, ParamSet p, const FileLoc& l) override {
    logNamed("volumeIntegrator", n, std::move(p), l);
  }
  void integrator(const std::string& n, ParamSet p, const FileLoc& l) override {
    logNamed("integrator", n, std::move(p), l);
  }
  void renderer(const std::string& n, ParamSet p, const FileLoc& l) override {
    logNamed("renderer", n, std::move(p), l);
  }
  void toneMap(const std::string& n, ParamSet p, const FileLoc& l) override {
    logNamed("toneMap", n, std::move(p), l);
  }
  void searchPath(const std::string& p, const FileLoc& l) override { log("searchPath " + p, l); }
  void makeNamedMedium(const std::string& n, ParamSet p, const FileLoc& l) override {
    logNamed("makeNamedMedium", n, std::move(p), l);
  }
  void mediumInterface(const std::string& a, const std::string& b, const FileLoc& l) override {
    log("mediumInterface " + a + "|" + b, l);
  }
  void worldBegin(const FileLoc& l) override { log("worldBegin", l); }
  void worldEnd(const FileLoc& l) override { log("worldEnd", l); }
  void attributeBegin(const FileLoc& l) override { log("attributeBegin", l); }
  void attributeEnd(const FileLoc& l) override { log("attributeEnd", l); }
  void texture(const std::string& n, const std::string& t, const std::string& c, ParamSet p,
               const FileLoc& l) override {
    logNamed("texture", n + " " + t + " " + c, std::move(p), l);
  }
  void material(const std::string& n, ParamSet p, const FileLoc& l) override {
    logNamed("material", n, std::move(p), l);
  }
  void makeNamedMaterial(const std::string& n, ParamSet p, const FileLoc& l) override {
    logNamed("makeNamedMaterial", n, std::move(p), l);
  }
  void namedMaterial(const std::string& n, const FileLoc& l) override {
    log("namedMaterial " + n, l);
  }
  void bumpMap(const std::string& n, ParamSet p, const FileLoc& l) override {
    logNamed("bumpMap", n, std::move(p), l);
  }
  void lightSource(const std::string& n, ParamSet p, const FileLoc& l) override {
    logNamed("lightSource", n, std::move(p), l);
  }
  void areaLightSource(const std::string& n, ParamSet p, const FileLoc& l) override {
    logNamed("areaLightSource", n, std::move(p), l);
  }
  void shape(const std::string& n, ParamSet p, const FileLoc& l) override {
    logNamed("shape", n, std::move(p), l);
  }
  void volume(const std::string& n, ParamSet p, const FileLoc& l) override {
    logNamed("volume", n, std::move(p), l);
  }
  void objectBegin(const std::string& n, const FileLoc& l) override { log("objectBegin " + n, l); }
  void objectEnd(const FileLoc& l) override { log("objectEnd", l); }
  void objectInstance(const std::string& n, const FileLoc& l) override {
    log("objectInstance " + n, l);
  }
  void endOfInput(const FileLoc& l) override { log("endOfInput", l); }
};

Recorder parse(const std::string& text, std::vector<std::string>* warnings = nullptr) {
  Recorder r;
  parseString(text, "t.pbrt", r, [&](const FileLoc& loc, const std::string& msg) {
    if (warnings) warnings->push_back(loc.str() + ": " + msg);
  });
  return r;
}

std::string errorOf(const std::string& text) {
  return test::sceneErrorOf([&] { parse(text); });
}

// A scratch directory for tests that need files.
struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const std::string& name)
      : path(std::filesystem::temp_directory_path() / ("candela_parser_" + name)) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~TempDir() { std::filesystem::remove_all(path); }
  std::string write(const std::string& rel, const std::string& text) const {
    std::filesystem::path p = path / rel;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p) << text;
    return p.string();
  }
};

}  // namespace

TEST(Parser, EveryDirectiveReachesTheTarget) {
  Recorder r = parse(R"(
SearchPath "a:&"
Identity
Translate 1 2 3
Scale 2 2 2
Rotate 90 0 0 1
LookAt 0 0 -5  0 0 0  0 1 0
Transform [1 0 0 0 0 1 0 0 0 0 1 0 5 6 7 1]
ConcatTransform [2 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1]
CoordinateSystem "mine"
CoordSysTransform "mine"
ActiveTransform StartTime
ActiveTransform EndTime
ActiveTransform All
TransformTimes 0 2
Camera "perspective" "float fov" 45
Sampler "random"
PixelFilter "box"
Film "image"
Accelerator "bvh"
SurfaceIntegrator "path"
VolumeIntegrator "single"
Integrator "path"
Renderer "sampler"
ToneMap "contrast"
MakeNamedMedium "fog" "string type" "homogeneous"
MediumInterface "fog"
MediumInterface "" "fog"
Option "bool disablepixeljitter" true
WorldBegin
AttributeBegin
TransformBegin
TransformEnd
ReverseOrientation
Texture "t" "color" "checkerboard"
Material "matte"
MakeNamedMaterial "m" "string type" "plastic"
NamedMaterial "m"
BumpMap "b"
LightSource "point"
AreaLightSource "area"
Shape "sphere"
Volume "homogeneous"
ObjectBegin "o"
ObjectEnd
ObjectInstance "o"
AttributeEnd
WorldEnd
)");
  std::vector<std::string> expected = {
      "searchPath a:& @t.pbrt:2:1",
      "identity @t.pbrt:3:1",
      "translate 1 2 3 @t.pbrt:4:1",
      "scale 2 2 2 @t.pbrt:5:1",
      "rotate 90 0 0 1 @t.pbrt:6:1",
      "lookAt 0 0 -5 0 0 0 0 1 0 @t.pbrt:7:1",
      "transform 1 5 1 @t.pbrt:8:1",
      "concatTransform 2 0 1 @t.pbrt:9:1",
      "coordinateSystem mine @t.pbrt:10:1",
      "coordSysTransform mine @t.pbrt:11:1",
      "activeStart @t.pbrt:12:1",
      "activeEnd @t.pbrt:13:1",
      "activeAll @t.pbrt:14:1",
      "transformTimes 0 2 @t.pbrt:15:1",
      "camera perspective @t.pbrt:16:1",
      "sampler random @t.pbrt:17:1",
      "pixelFilter box @t.pbrt:18:1",
      "film image @t.pbrt:19:1",
      "accelerator bvh @t.pbrt:20:1",
      "surfaceIntegrator path @t.pbrt:21:1",
      "volumeIntegrator single @t.pbrt:22:1",
      "integrator path @t.pbrt:23:1",
      "renderer sampler @t.pbrt:24:1",
      "toneMap contrast @t.pbrt:25:1",
      "makeNamedMedium fog @t.pbrt:26:1",
      "mediumInterface fog|fog @t.pbrt:27:1",
      "mediumInterface |fog @t.pbrt:28:1",
      "worldBegin @t.pbrt:30:1",
      "attributeBegin @t.pbrt:31:1",
      "transformBegin @t.pbrt:32:1",
      "transformEnd @t.pbrt:33:1",
      "reverseOrientation @t.pbrt:34:1",
      "texture t color checkerboard @t.pbrt:35:1",
      "material matte @t.pbrt:36:1",
      "makeNamedMaterial m @t.pbrt:37:1",
      "namedMaterial m @t.pbrt:38:1",
      "bumpMap b @t.pbrt:39:1",
      "lightSource point @t.pbrt:40:1",
      "areaLightSource area @t.pbrt:41:1",
      "shape sphere @t.pbrt:42:1",
      "volume homogeneous @t.pbrt:43:1",
      "objectBegin o @t.pbrt:44:1",
      "objectEnd @t.pbrt:45:1",
      "objectInstance o @t.pbrt:46:1",
      "attributeEnd @t.pbrt:47:1",
      "worldEnd @t.pbrt:48:1",
  };
  EXPECT_EQ(r.calls, expected);
}

TEST(Parser, ParameterTypesAndValues) {
  Recorder r = parse(R"(Shape "x"
  "integer indices" [0 1 2] "float radius" 2.5 "float  tex2" [-.25]
  "point P" [0 0 0 1 1 1] "point3 p3" [1 2 3] "vector v" [0 0 1] "vector3 v3" [1 0 0]
  "normal N" [0 1 0] "normal3 N3" [0 0 1] "point2 uv2" [0 1] "vector2 d2" [1 0]
  "color Kd" [.5 .5 .5] "rgb Ks" [1 0 0] "bool a" "true" "bool b" ["false"] "bool c" true
  "string filename" "a b.exr" "texture tex" "checks" "uniform float u" 1
  "float cropwindow[4]" [0 1 0 1])");
  ASSERT_EQ(r.params.size(), 1u);
  const ParamSet& ps = r.params[0];
  EXPECT_EQ(ps.getIntArray("indices"), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(ps.getOneFloat("radius", 0), 2.5f);
  EXPECT_EQ(ps.getOneFloat("tex2", 0), -.25f);
  EXPECT_EQ(ps.getPoint3fArray("P").size(), 2u);
  EXPECT_EQ(ps.getOnePoint3f("p3", Point3f()), Point3f(1, 2, 3));
  EXPECT_EQ(ps.getOneVector3f("v", Vector3f()).z, 1.f);
  EXPECT_EQ(ps.getOneVector3f("v3", Vector3f()).x, 1.f);
  EXPECT_EQ(ps.getOneNormal3f("N", Normal3f()).y, 1.f);
  EXPECT_EQ(ps.getOneNormal3f("N3", Normal3f()).z, 1.f);
  EXPECT_EQ(ps.getPoint2fArray("uv2")[0], Point2f(0, 1));
  EXPECT_EQ(ps.find("d2")->type, ParamType::Vector2);
  EXPECT_EQ(ps.getOneSpectrum("Kd", Spectrum()), Spectrum(.5f));
  EXPECT_EQ(ps.getOneSpectrum("Ks", Spectrum()), Spectrum(1, 0, 0));
  EXPECT_EQ(ps.find("Ks")->typeName, "rgb");
  EXPECT_TRUE(ps.getOneBool("a", false));
  EXPECT_FALSE(ps.getOneBool("b", true));
  EXPECT_TRUE(ps.getOneBool("c", false));
  EXPECT_EQ(ps.getOneString("filename", ""), "a b.exr");
  EXPECT_EQ(ps.getTexture("tex"), "checks");
  EXPECT_EQ(ps.getOneFloat("u", 0), 1.f);
  EXPECT_EQ(ps.getFloatArray("cropwindow").size(), 4u);
  EXPECT_EQ(ps.find("radius")->loc.str(), "t.pbrt:2:29");
}

TEST(Parser, SpectralParametersBecomeRgb) {
  Recorder r = parse(R"(Material "matte"
  "spectrum flat" [300 1 800 1] "xyz white" [0.950456 1 1.088754]
  "blackbody v2" [6500 2] "blackbody v3" 6500 "blackbody L" [6500 1 3000 1])");
  const ParamSet& ps = r.params[0];
  Spectrum flat = ps.getOneSpectrum("flat", Spectrum());
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(flat[c], 1, 0.02);
  Spectrum white = ps.getOneSpectrum("white", Spectrum());
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(white[c], 1, 0.001);
  EXPECT_NEAR(ps.getOneSpectrum("v2", Spectrum()).g(), 2 * ps.getOneSpectrum("v3", Spectrum()).g(),
              1e-4);
  EXPECT_EQ(ps.getSpectrumArray("L").size(), 2u);
}

TEST(Parser, SpectrumFilesAreRelativeToTheIncludingFile) {
  TempDir dir("spd");
  dir.write("spds/flat.spd", "# flat\n300 2\n900 2\n");
  dir.write("sub/part.pbrt", "Material \"metal\" \"spectrum eta\" \"../spds/flat.spd\"\n");
  std::string main = dir.write("main.pbrt", "Include \"sub/part.pbrt\"\n");
  Recorder r;
  parseFile(main, r);
  ASSERT_EQ(r.params.size(), 1u);
  EXPECT_NEAR(r.params[0].getOneSpectrum("eta", Spectrum()).g(), 2, 0.04);
  EXPECT_EQ(r.calls[0], "material metal @" + (dir.path / "sub/part.pbrt").string() + ":1:1");
}

TEST(Parser, IncludeAndImport) {
  TempDir dir("include");
  dir.write("geometry/a.pbrt", "Shape \"sphere\"\nInclude \"b.pbrt\"\n");
  dir.write("geometry/b.pbrt", "Shape \"disk\"\n");
  std::string main = dir.write(
      "main.pbrt", "WorldBegin\nInclude \"geometry/a.pbrt\"\nImport \"geometry/b.pbrt\"\n");
  Recorder r;
  parseFile(main, r);
  ASSERT_EQ(r.calls.size(), 4u);
  EXPECT_EQ(r.calls[1], "shape sphere @" + (dir.path / "geometry/a.pbrt").string() + ":1:1");
  EXPECT_EQ(r.calls[2], "shape disk @" + (dir.path / "geometry/b.pbrt").string() + ":1:1");
  EXPECT_EQ(r.calls[3], "shape disk @" + (dir.path / "geometry/b.pbrt").string() + ":1:1");
}

// A caller's reader serves the files a scene names (the parser fuzzer's in-memory files): paths
// reach it resolved against the naming file, and cycles are found by path without the filesystem.
TEST(Parser, NamedFilesComeFromTheCallersReader) {
  std::map<std::string, std::string> files = {
      {"/mem/geometry/a.pbrt", "Material \"metal\" \"spectrum eta\" \"../flat.spd\"\n"},
      {"/mem/flat.spd", "300 2\n900 2\n"},
      {"/mem/loop.pbrt", "Include \"./geometry/../loop.pbrt\""}};
  std::vector<std::string> asked;
  SceneFileReader read = [&](const std::string& path) {
    asked.push_back(path);
    auto it = files.find(path);
    if (it == files.end()) throw FileError(path, "no such file");
    return it->second;
  };
  Recorder r;
  parseString("Include \"geometry/a.pbrt\"\n", "/mem/main.pbrt", r, {}, read);
  ASSERT_EQ(r.params.size(), 1u);
  EXPECT_NEAR(r.params[0].getOneSpectrum("eta", Spectrum()).g(), 2, 0.04);
  EXPECT_EQ(asked, (std::vector<std::string>{"/mem/geometry/a.pbrt", "/mem/flat.spd"}));
  try {
    parseString("Include \"loop.pbrt\"", "/mem/main.pbrt", r, {}, read);
    FAIL() << "expected an include cycle error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("/mem/loop.pbrt:1:9: error: include cycle"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(parseString("Include \"none.pbrt\"", "/mem/main.pbrt", r, {}, read), SceneError);
}

TEST(Parser, OptionIsAcceptedWithAWarning) {
  std::vector<std::string> warnings;
  Recorder r =
      parse("Option \"bool disablepixeljitter\" true\nOption \"string x\" [\"y\"]", &warnings);
  EXPECT_TRUE(r.calls.empty());
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[0], "t.pbrt:1:1: Option \"disablepixeljitter\" is not supported; ignored");
}

TEST(Parser, ParsingDoesNotCallEndOfInput) {
  Recorder r = parse("WorldBegin\n");
  EXPECT_EQ(r.calls.size(), 1u);
}

// ---- One test per error kind, each with its exact location ------------------------------------

TEST(ParserErrors, UnknownDirective) {
  EXPECT_EQ(errorOf("WorldBegin\n  Shpe \"sphere\""),
            "t.pbrt:2:3: error: unknown directive 'Shpe'");
}

TEST(ParserErrors, DirectiveExpected) {
  EXPECT_EQ(errorOf("Shape \"sphere\" 1 2"),
            "t.pbrt:1:16: error: expected a directive, found number 1");
}

TEST(ParserErrors, QuotedNameExpected) {
  EXPECT_EQ(errorOf("Shape sphere"),
            "t.pbrt:1:7: error: 'Shape' needs a name as a quoted string, found 'sphere'");
}

TEST(ParserErrors, NumberArgumentExpected) {
  EXPECT_EQ(errorOf("Translate 1 \"two\" 3"),
            "t.pbrt:1:13: error: 'Translate' needs 3 numbers, found string \"two\"");
}

TEST(ParserErrors, WrongMatrixSize) {
  EXPECT_EQ(errorOf("Transform [1 0 0 0\n 0 1 0 0 ]"),
            "t.pbrt:2:10: error: 'Transform' needs 16 numbers, found 8");
}

TEST(ParserErrors, TruncatedStatement) {
  EXPECT_EQ(errorOf("LookAt 0 0 1\n"),
            "t.pbrt:2:1: error: 'LookAt' needs 9 numbers, found end of file");
}

TEST(ParserErrors, BadActiveTransform) {
  EXPECT_EQ(
      errorOf("ActiveTransform Middle"),
      "t.pbrt:1:17: error: 'ActiveTransform' needs All, StartTime or EndTime, found 'Middle'");
}

TEST(ParserErrors, UnknownParameterType) {
  EXPECT_EQ(errorOf("Shape \"sphere\" \"flaot radius\" 1"),
            "t.pbrt:1:16: error: unknown parameter type 'flaot' in string \"flaot radius\"");
}

TEST(ParserErrors, MalformedDeclaration) {
  EXPECT_EQ(errorOf("Shape \"sphere\" \"radius\" 1"),
            "t.pbrt:1:16: error: expected a parameter declaration \"type name\", found string "
            "\"radius\"");
}

TEST(ParserErrors, StringWhereNumberExpected) {
  EXPECT_EQ(errorOf("Shape \"sphere\" \"float radius\" [ 1 \"big\" ]"),
            "t.pbrt:1:35: error: parameter \"float radius\" expects numbers, found string \"big\"");
}

TEST(ParserErrors, NumberWhereStringExpected) {
  EXPECT_EQ(errorOf("Film \"image\"\n  \"string filename\" 3"),
            "t.pbrt:2:21: error: parameter \"string filename\" expects quoted strings, found "
            "number 3");
}

TEST(ParserErrors, NonIntegerInteger) {
  EXPECT_EQ(errorOf("Shape \"x\" \"integer n\" [1 2.5]"),
            "t.pbrt:1:26: error: parameter \"integer n\" expects integers, found number 2.5");
}

TEST(ParserErrors, BadBool) {
  EXPECT_EQ(errorOf("Shape \"x\" \"bool b\" \"yes\""),
            "t.pbrt:1:20: error: parameter \"bool b\" expects true or false, found string \"yes\"");
}

TEST(ParserErrors, WrongTupleCount) {
  EXPECT_EQ(errorOf("Shape \"x\"\n \"point P\" [0 0 0 1]"),
            "t.pbrt:2:2: error: parameter \"point P\" needs a multiple of 3 numbers, found 4");
}

TEST(ParserErrors, MissingValue) {
  EXPECT_EQ(errorOf("Shape \"x\" \"float r\""),
            "t.pbrt:1:20: error: expected a value for parameter \"float r\", found end of file");
}

TEST(ParserErrors, UnclosedBracket) {
  EXPECT_EQ(errorOf("Shape \"x\" \"float r\" [ 1 2\n"),
            "t.pbrt:1:21: error: '[' of parameter \"float r\" is never closed");
}

TEST(ParserErrors, NestedBracket) {
  EXPECT_EQ(errorOf("Shape \"x\" \"float r\" [ 1 [ 2 ] ]"),
            "t.pbrt:1:25: error: unexpected '[' inside the values of parameter \"float r\"");
}

TEST(ParserErrors, OddSpectrumPairs) {
  EXPECT_EQ(errorOf("Material \"m\" \"spectrum Kd\" [400 1 500]"),
            "t.pbrt:1:14: error: parameter \"spectrum Kd\" needs (wavelength, value) pairs, "
            "found 3 numbers");
}

TEST(ParserErrors, BadBlackbody) {
  EXPECT_EQ(errorOf("LightSource \"point\" \"blackbody I\" [-5 1]"),
            "t.pbrt:1:36: error: parameter \"blackbody I\" needs a temperature above 0 K, found "
            "number -5");
  EXPECT_EQ(errorOf("LightSource \"point\" \"blackbody I\" [6500 1 3]"),
            "t.pbrt:1:21: error: parameter \"blackbody I\" needs one temperature or (temperature, "
            "scale) pairs, found 3 numbers");
}

// Found by fuzz_spd: a spectrum file "401 3.3e38" (values within float range) converted to an
// infinite colour, and so did such spectra, XYZ values and blackbody scales written inline.
TEST(ParserErrors, SpectraBeyondTheFloatRange) {
  const std::string beyond = " gives a colour beyond the float range";
  EXPECT_EQ(errorOf("Material \"matte\" \"spectrum Kd\" [401 3.3e38]"),
            "t.pbrt:1:33: error: parameter \"spectrum Kd\"" + beyond);
  EXPECT_EQ(errorOf("Material \"matte\" \"xyz Kd\" [1 1 1  3e38 3e38 3e38]"),
            "t.pbrt:1:35: error: parameter \"xyz Kd\"" + beyond);
  EXPECT_EQ(errorOf("LightSource \"point\" \"blackbody I\" [6500 3e38]"),
            "t.pbrt:1:36: error: parameter \"blackbody I\"" + beyond);
  SceneFileReader read = [](const std::string&) {
    return std::string("401 0333333333333333333333333333333333333333");
  };
  Recorder r;
  try {
    parseString("Material \"matte\"\n  \"spectrum Kd\" \"s.spd\"", "/m/t.pbrt", r, {}, read);
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), "/m/t.pbrt:2:17: error: parameter \"spectrum Kd\"" + beyond);
  }
  // Large but representable colours stay.
  EXPECT_EQ(errorOf("Material \"matte\" \"spectrum Kd\" [400 1e30 700 1e30]"), "(no error)");
}

TEST(ParserErrors, MissingSpectrumFile) {
  std::string e = errorOf("Material \"metal\"\n \"spectrum eta\" \"nowhere/Au.eta.spd\"");
  EXPECT_EQ(e.rfind("t.pbrt:2:17: error: cannot read spectrum of parameter \"spectrum eta\": ", 0),
            0u)
      << e;
}

TEST(ParserErrors, MissingIncludedFile) {
  std::string e = errorOf("WorldBegin\nInclude \"nowhere.pbrt\"");
  EXPECT_EQ(e.rfind("t.pbrt:2:9: error: cannot read included file: ", 0), 0u) << e;
  EXPECT_NE(e.find("nowhere.pbrt: error: no such file"), std::string::npos) << e;
}

TEST(ParserErrors, IncludeCycle) {
  TempDir dir("cycle");
  dir.write("a.pbrt", "Shape \"sphere\"\nInclude \"b.pbrt\"\n");
  std::string b = dir.write("b.pbrt", "\n  Include \"a.pbrt\"\n");
  std::string a = (dir.path / "a.pbrt").string();
  Recorder r;
  try {
    parseFile(a, r);
    FAIL() << "expected an include cycle error";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()),
              b + ":2:11: error: include cycle: 'a.pbrt' is already being parsed");
  }
}

TEST(ParserErrors, MissingTopLevelFileIsAFileError) {
  Recorder r;
  EXPECT_THROW(parseFile("/nonexistent/candela/scene.pbrt", r), FileError);
  EXPECT_THROW(parseFile(std::filesystem::temp_directory_path().string(), r), FileError);
}

TEST(ParserErrors, TokenizerErrorsPassThrough) {
  EXPECT_EQ(errorOf("Shape \"sphere\" \"float radius\" [1e400]"),
            "t.pbrt:1:32: error: number '1e400' is out of range");
  EXPECT_EQ(errorOf("Shape \"sphere\" \"float radius\" nan"),
            "t.pbrt:1:31: error: parameter \"float radius\" expects numbers, found 'nan'");
}
