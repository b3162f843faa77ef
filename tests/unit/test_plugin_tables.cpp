// Every plug-in table's declarations checked against what the plug-in really does, in each
// dialect it belongs to:
//   - every parameter name its create function asks its statement for is declared;
//   - every declared parameter with a constant default is read (no unused-parameter warning
//     when all of them are given), and giving them all at their declared defaults changes no bit
//     of the image (so the declared defaults are the code's);
//   - every declared rule is enforced: a value just outside it is a SceneError naming the
//     parameter.
// The scene around each plug-in is a small fixed one (8x8 pixels, one sample); plug-ins that
// need parameters without defaults get them from kRequired.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <map>
#include <memory>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "assembly/plugin_registry.h"
#include "assembly/render_job.h"
#include "parser/parser.h"
#include "parser/scene_builder.h"
#include "support/fourier_bsdf_writer.h"
#include "support/render_scene.h"
#include "support/temp_dir.h"
#include "support/test_device.h"

namespace candela {
namespace {

enum class Dialect { V2, V3 };

// Parameters a plug-in needs to be made at all (no default), in scene syntax, by "kind/name".
const std::map<std::string, std::string> kRequired = {
    {"shape/trianglemesh", R"("point3 P" [-1 -1 0 1 -1 0 0 1 0] "integer indices" [0 1 2])"},
    {"shape/loopsubdiv",
     R"("point3 P" [-1 -1 0 1 -1 0 0 1 0 0 0 1] "integer indices" [0 1 2 0 2 3 0 3 1 1 3 2])"},
    {"shape/heightfield", R"("integer nu" [2] "integer nv" [2] "float Pz" [0 1 0 1])"},
    {"shape/nurbs",
     R"("integer nu" [2] "integer nv" [2] "integer uorder" [2] "integer vorder" [2]
        "float uknots" [0 0 1 1] "float vknots" [0 0 1 1] "float u0" [0] "float u1" [1]
        "float v0" [0] "float v1" [1] "point P" [-1 -1 0 1 -1 0 -1 1 0 1 1 0])"},
    {"shape/curve", R"("point3 P" [-1 0 0 -0.3 0.5 0 0.3 -0.5 0 1 0 0])"},
    {"shape/plymesh", R"("string filename" "@DATA@/triangle.ply")"},
    {"material/mix", R"("string namedmaterial1" "a" "string namedmaterial2" "b")"},
    {"material/fourier", R"("string bsdffile" "@DATA@/lambertian.bsdf")"},
    {"material/measured", R"("string filename" "@DATA@/tiny.brdf")"},
    {"texture/imagemap", R"("string filename" "fake.png")"},
    {"volume region/volumegrid", R"("float density" [1])"},
    {"medium/heterogeneous", R"("float density" [1])"},
    {"camera/realistic", R"("string lensfile" "@LENSES@/biconvex.dat")"},
};

// The statement(s) of the small scene that hold plug-in `name` of `kind` with `params`.
struct SceneParts {
  std::string film = R"(Film "image" "integer xresolution" [8] "integer yresolution" [8])";
  std::string sampler = R"(Sampler "random" "integer pixelsamples" [1])";
  std::string filter = R"(PixelFilter "box")";
  std::string camera = R"(Camera "perspective" "float fov" [40])";
  std::string accelerator;
  std::string integrator;
  std::string volumeIntegrator, renderer, volume, medium;
  std::string light = R"(LightSource "point" "point from" [0 2 -3] "rgb I" [10 10 10])";
  std::string material = R"(Material "matte")";
  std::string texture, shape = R"(Shape "sphere" "float radius" [1])";
  std::string areaLight;
};

std::string sceneText(const std::string& kind, const std::string& name, const std::string& params,
                      Dialect dialect) {
  SceneParts s;
  s.integrator = dialect == Dialect::V3 ? R"(Integrator "path" "integer maxdepth" [2])"
                                        : R"(SurfaceIntegrator "directlighting")";
  std::string stmt = "\"" + name + "\" " + params;
  if (kind == "camera") s.camera = "Camera " + stmt;
  if (kind == "sampler") s.sampler = "Sampler " + stmt;
  if (kind == "filter") s.filter = "PixelFilter " + stmt;
  if (kind == "film")
    s.film = "Film " + stmt + R"( "integer xresolution" [8] "integer yresolution" [8])";
  if (kind == "accelerator") s.accelerator = "Accelerator " + stmt;
  if (kind == "integrator")
    s.integrator = (dialect == Dialect::V3 ? "Integrator " : "SurfaceIntegrator ") + stmt;
  if (kind == "renderer") s.renderer = "Renderer " + stmt;
  if (kind == "volume integrator" || kind == "volume region") {
    s.volumeIntegrator =
        kind == "volume integrator" ? "VolumeIntegrator " + stmt : R"(VolumeIntegrator "single")";
    s.volume = kind == "volume region"
                   ? "Volume " + stmt
                   : R"(Volume "homogeneous" "rgb sigma_a" [0.1 0.1 0.1] "rgb sigma_s" [0.1 0.1 0.1]
                        "point p0" [-2 -2 -2] "point p1" [2 2 2])";
  }
  if (kind == "medium") {
    s.integrator = R"(Integrator "volpath" "integer maxdepth" [2])";
    s.medium = "MakeNamedMedium \"fog\" \"string type\" " + stmt;
    s.material = R"(Material "" MediumInterface "fog" "")";
  }
  if (kind == "shape") s.shape = "Shape " + stmt;
  if (kind == "material") {
    // Specular materials show what they reflect.
    s.light += "\nLightSource \"infinite\" \"rgb L\" [0.3 0.3 0.3]";
    s.material = R"(MakeNamedMaterial "a" "string type" "matte"
                    MakeNamedMaterial "b" "string type" "mirror"
                    Material )" +
                 stmt;
  }
  if (kind == "bump map") s.material = "BumpMap " + stmt + "\nMaterial \"matte\"";
  if (kind == "texture") {
    s.texture = "Texture \"t\" \"spectrum\" " + stmt;
    s.material = R"(Material "matte" "texture Kd" "t")";
  }
  if (kind == "light") {
    // Lights default to the origin: the sphere goes in front of them, facing the camera.
    s.light = "LightSource " + stmt;
    s.shape = "Translate 0 0 3\n" + s.shape;
  }
  if (kind == "area light") s.areaLight = "AreaLightSource " + stmt;
  std::ostringstream o;
  o << "LookAt 0 0 -4  0 0 0  0 1 0\n"
    << s.film << "\n"
    << s.sampler << "\n"
    << s.filter << "\n"
    << s.camera << "\n"
    << s.accelerator << "\n"
    << s.integrator << "\n"
    << s.volumeIntegrator << "\n"
    << s.renderer << "\nWorldBegin\n"
    << s.medium << "\n"
    << s.volume << "\n"
    << s.light << "\n"
    << s.texture << "\nAttributeBegin\n"
    << s.material << "\n"
    << s.areaLight << "\n"
    << s.shape << "\nAttributeEnd\nWorldEnd\n";
  return o.str();
}

// The ParamSets of the scene's statements of that kind (the plug-in's, since the scene has one).
std::vector<ParamSet*> statementsOf(SceneDescription& d, const std::string& kind,
                                    const std::string& name) {
  std::vector<ParamSet*> out;
  auto add = [&](PluginDesc& p) {
    if (p.name == name) out.push_back(&p.params);
  };
  if (kind == "camera") add(d.camera);
  if (kind == "sampler") add(d.sampler);
  if (kind == "filter") add(d.filter);
  if (kind == "film") add(d.film);
  if (kind == "accelerator") add(d.accelerator);
  if (kind == "integrator") {
    add(d.surfaceIntegrator);
    add(d.integrator);
  }
  if (kind == "volume integrator") add(d.volumeIntegrator);
  if (kind == "renderer") add(d.renderer);
  if (kind == "volume region")
    for (auto& v : d.volumes) add(v);
  if (kind == "medium")
    for (auto& m : d.media) add(m);
  if (kind == "shape")
    for (auto& s : d.shapes) add(s);
  if (kind == "area light")
    for (auto& s : d.shapes)
      if (s.areaLight) add(*s.areaLight);
  if (kind == "material")
    for (auto& m : d.materials) add(m);
  if (kind == "bump map")
    for (auto& m : d.materials)
      if (m.bumpMap) add(*m.bumpMap);
  if (kind == "texture")
    for (auto& t : d.textures) add(t);
  if (kind == "light")
    for (auto& l : d.lights) add(l);
  return out;
}

struct Outcome {
  std::vector<float> pixels;
  std::set<std::string> queried;
  std::vector<std::string> unused;  // unused-parameter warnings
};

BuildOptions buildOptions(Dialect dialect, std::vector<std::string>* warnings) {
  BuildOptions b;
  b.seed = 7;
  b.nThreads = 1;
  if (dialect == Dialect::V3) b.compatibility.dialect = SceneDialect::PbrtV3;
  b.warn = [warnings](const FileLoc&, const std::string& m) { warnings->push_back(m); };
  b.loadImage = [](const std::string&, const std::string&) {
    ImageBuffer img(4, 2, {"R", "G", "B"});
    for (size_t i = 0; i < img.data.size(); ++i) img.data[i] = float(i % 5) / 4;
    return img;
  };
  return b;
}

// Throws what the build throws.
Outcome run(const std::string& text, const std::string& kind, const std::string& name,
            Dialect dialect, bool render) {
  Outcome out;
  std::vector<std::string> warnings;
  BuildOptions build = buildOptions(dialect, &warnings);
  auto queried = std::make_shared<std::set<std::string>>();
  SceneBuilder builder(
      [&](SceneDescription&& desc) {
        for (ParamSet* p : statementsOf(desc, kind, name)) p->recordQueries(queried);
        RenderJob job = buildRenderJob(desc, build, test::embreeDevice());
        if (!render) return;
        ProgressiveOptions po;
        po.render = RenderOptions{1, 16, true};
        renderJob(job, po);
        for (const Spectrum& s : test::pixelValues(*job.film))
          for (int c = 0; c < 3; ++c) out.pixels.push_back(s[c]);
      },
      {});
  parseString(text, "plugin-test.pbrt", builder);
  builder.endOfInput(FileLoc{"plugin-test.pbrt", 0, 0});
  out.queried = *queried;
  for (const std::string& w : warnings)
    if (w.find("was not used") != std::string::npos) out.unused.push_back(w);
  return out;
}

bool isConstant(std::string_view def) { return !def.empty() && def.front() != '('; }

// "float texture" -> "float", "spectrum texture" -> "rgb", "point3[]" -> "point3".
std::string sceneType(std::string_view type) {
  std::string t(type);
  if (t.size() > 2 && t.substr(t.size() - 2) == "[]") t.resize(t.size() - 2);
  if (t.size() > 8 && t.substr(t.size() - 8) == " texture") t.resize(t.size() - 8);
  // Textures of both types are tested as spectrum textures.
  if (t == "spectrum" || t == "float or spectrum") t = "rgb";
  if (t == "float or bool") t = "float";
  return t;
}

// The item `"type name" [value]`, a single number repeated for a colour.
std::string item(const ParamSpec& p, const std::string& value) {
  std::string type = sceneType(p.type);
  std::string v = value;
  if (type == "rgb" && v.find(' ') == std::string::npos) v = v + " " + v + " " + v;
  if (type == "string" || type == "bool") v = "\"" + v + "\"";
  return "\"" + type + " " + std::string(p.name) + "\" [" + v + "] ";
}

unsigned maskOf(Dialect d) { return d == Dialect::V3 ? kPbrtV3 : kLrt | kPbrtV2 | kCandela; }
bool inDialect(unsigned mask, Dialect d) {
  return (mask & maskOf(d)) != 0 || (d == Dialect::V2 && mask == kCandela);
}

// A value just outside the rule, or "" when the rule has none writable in a scene file.
std::string outside(std::string_view rule, bool integer) {
  std::smatch m;
  std::string r(rule);
  auto num = [&](double v) {
    std::ostringstream o;
    o << std::setprecision(17) << (integer ? std::floor(v) : v);
    return o.str();
  };
  if (r == "positive and finite") return "0";
  if (r == "non-negative and finite") return "-1";
  if (std::regex_match(r, m, std::regex(R"(at least (\S+))")))
    return num(std::stod(m[1]) - (integer ? 1 : 0.5));
  if (std::regex_match(r, m, std::regex(R"(greater than (\S+))"))) return num(std::stod(m[1]));
  if (std::regex_match(r, m, std::regex(R"(within ([\[(])(\S+), (\S+)([\])]))"))) {
    double hi = std::stod(m[3]);
    return num(m[4] == "]" ? hi + 1 : hi);
  }
  if (r.rfind("one of ", 0) == 0) return "no-such-choice";
  return "";
}

struct Case {
  std::string kind;
  const PluginSpec* spec;
  Dialect dialect;
};

std::vector<Case> allCases() {
  std::vector<Case> cases;
  for (const PluginKind& k : pluginKinds())
    for (const PluginSpec* p : k.plugins)
      for (Dialect d : {Dialect::V2, Dialect::V3})
        if (inDialect(p->dialects, d)) cases.push_back({std::string(k.kind), p, d});
  return cases;
}

void PrintTo(const Case& c, std::ostream* os) {
  *os << c.kind << " '" << c.spec->name << "' ("
      << (c.dialect == Dialect::V3 ? "pbrt-v3" : "pbrt-v2") << ")";
}

std::string caseName(const testing::TestParamInfo<Case>& info) {
  std::string n = info.param.kind + "_" + std::string(info.param.spec->name) +
                  (info.param.dialect == Dialect::V3 ? "_v3" : "_v2");
  for (char& c : n)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return n;
}

class PluginTable : public testing::TestWithParam<Case> {
 protected:
  void SetUp() override {
    dir_ = std::make_unique<TempDir>("plugins");
    dir_->write("triangle.ply",
                "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                "end_header\n-1 -1 0\n1 -1 0\n0 1 0\n3 0 1 2\n");
    dir_->write("tiny.brdf",
                "1\n550\n0.5 0 0.5 3.14159 0.3\n0.3 0 0.3 3.14159 0.3\n"
                "0.8 1 0.8 4 0.3\n");
    dir_->write("lambertian.bsdf",
                test::fourierBsdfFileBytes(test::lambertianModel(0.5), test::splitUniformNodes(4)));
  }
  Outcome run(const std::string& text) const {
    return candela::run(text, GetParam().kind, std::string(GetParam().spec->name),
                        GetParam().dialect, false);
  }
  Outcome render(const std::string& text) const {
    return candela::run(text, GetParam().kind, std::string(GetParam().spec->name),
                        GetParam().dialect, true);
  }
  std::unique_ptr<TempDir> dir_;
  std::string required() const {
    auto it = kRequired.find(GetParam().kind + "/" + std::string(GetParam().spec->name));
    if (it == kRequired.end()) return "";
    std::string s = it->second;
    for (auto [key, value] : {std::pair<std::string, std::string>{"@DATA@", dir_->path("")},
                              {"@LENSES@", std::string(CANDELA_TEST_DATA_DIR) + "/lenses"}})
      for (size_t at = s.find(key); at != std::string::npos; at = s.find(key))
        s.replace(at, key.size(), value);
    return s;
  }
  // Names the scene itself sets for this plug-in (required ones, the film's resolution).
  bool setByScene(std::string_view name) const {
    std::string quoted = " " + std::string(name) + "\"";
    if (required().find(quoted) != std::string::npos) return true;
    return GetParam().kind == "film" && (name == "xresolution" || name == "yresolution");
  }
  std::string text(const std::string& params) const {
    return sceneText(GetParam().kind, std::string(GetParam().spec->name), required() + params,
                     GetParam().dialect);
  }
  std::string defaultOf(const ParamSpec& p) const {
    if (GetParam().dialect == Dialect::V3 && !p.pbrtV3Default.empty())
      return std::string(p.pbrtV3Default);
    return std::string(p.defaultValue);
  }
};

TEST_P(PluginTable, DeclaresEveryParameterItReads) {
  const Case& c = GetParam();
  Outcome o = run(text(""));
  std::set<std::string> declared;
  for (const ParamSpec& p : c.spec->params) declared.insert(std::string(p.name));
  for (const std::string& name : o.queried)
    EXPECT_TRUE(declared.count(name) || name == "type")
        << c.kind << " '" << c.spec->name << "' reads \"" << name
        << "\", which it does not declare";
}

TEST_P(PluginTable, ReadsEveryDeclaredParameterAndItsDefaultIsTheCodes) {
  const Case& c = GetParam();
  std::string given;
  for (const ParamSpec& p : c.spec->params)
    if (isConstant(defaultOf(p)) && inDialect(p.dialects, c.dialect) && !setByScene(p.name) &&
        p.onlyWhen.empty())
      given += item(p, defaultOf(p));
  Outcome plain = render(text(""));
  Outcome explicitDefaults = render(text(given));
  for (const std::string& w : explicitDefaults.unused)
    ADD_FAILURE() << "declared but not read: " << w;
  ASSERT_EQ(plain.pixels.size(), explicitDefaults.pixels.size());
  size_t differing = 0;
  for (size_t i = 0; i < plain.pixels.size(); ++i)
    differing += plain.pixels[i] != explicitDefaults.pixels[i] &&
                 !(std::isnan(plain.pixels[i]) && std::isnan(explicitDefaults.pixels[i]));
  EXPECT_EQ(differing, 0u) << "giving the declared defaults " << given << "changed the image";
  // A black image would hide any default.
  bool lit = false;
  for (float v : plain.pixels) lit |= v != 0;
  EXPECT_TRUE(lit) << "the scene renders black";
}

TEST_P(PluginTable, EnforcesEveryDeclaredRule) {
  const Case& c = GetParam();
  for (const ParamSpec& p : c.spec->params) {
    if (!inDialect(p.dialects, c.dialect) || setByScene(p.name)) continue;
    std::string bad = outside(p.rule, sceneType(p.type) == "integer");
    if (bad.empty()) continue;
    std::string given = item(p, bad);
    try {
      run(text(given));
      ADD_FAILURE() << given << "is outside \"" << p.rule << "\" but was accepted";
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find(std::string(p.name)), std::string::npos)
          << given << ": the error does not name the parameter: " << e.what();
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllPlugins, PluginTable, testing::ValuesIn(allCases()), caseName);

TEST(PluginTables, NamesAreUniqueWithinEachKindAndEveryEntryIsDescribed) {
  for (const PluginKind& k : pluginKinds()) {
    std::set<std::string_view> names;
    EXPECT_FALSE(k.plugins.empty()) << k.kind;
    for (const PluginSpec* p : k.plugins) {
      EXPECT_TRUE(names.insert(p->name).second) << k.kind << " '" << p->name << "' twice";
      EXPECT_EQ(p->kind, k.kind) << p->name;
      EXPECT_FALSE(p->summary.empty()) << k.kind << " '" << p->name << "'";
      std::set<std::string_view> params;
      for (const ParamSpec& q : p->params) {
        EXPECT_TRUE(params.insert(q.name).second) << p->name << ": \"" << q.name << "\" twice";
        EXPECT_FALSE(q.defaultValue.empty()) << p->name << ": \"" << q.name << "\"";
      }
    }
  }
}

TEST(PluginTables, UnknownNamesListTheTable) {
  for (const char* kind : {"shape", "material", "light", "camera", "sampler", "integrator"}) {
    std::string text = sceneText(kind, "no-such-plugin", "", Dialect::V2);
    try {
      run(text, kind, "no-such-plugin", Dialect::V2, false);
      ADD_FAILURE() << kind << ": an unknown name was accepted";
    } catch (const SceneError& e) {
      std::string message = e.what();
      for (const PluginKind& k : pluginKinds()) {
        if (k.kind != kind) continue;
        for (const PluginSpec* p : k.plugins) {
          EXPECT_NE(message.find(std::string(p->name)), std::string::npos)
              << kind << ": the error does not list '" << p->name << "': " << message;
        }
      }
    }
  }
}

TEST(PluginTables, DescribeAndListComeFromTheTables) {
  std::string list = listPlugins("material");
  for (const PluginKind& k : pluginKinds()) {
    if (k.kind != "material") continue;
    for (const PluginSpec* p : k.plugins) {
      EXPECT_NE(list.find(std::string(p->name)), std::string::npos) << p->name;
    }
  }
  EXPECT_TRUE(listPlugins("no-such-kind").empty());
  std::string hair = describePlugins("material/hair");
  EXPECT_NE(hair.find("\"float texture beta_m\""), std::string::npos) << hair;
  EXPECT_NE(hair.find("within (0, 1]"), std::string::npos) << hair;
  EXPECT_TRUE(describePlugins("no-such-plugin").empty());
}

// The README's one-screen table of what is supported names every plug-in of the kinds it lists,
// so that a new table entry cannot be missing from it.
TEST(PluginTables, TheReadmeTableNamesEveryPlugin) {
  std::ifstream in(std::string(CANDELA_SOURCE_DIR) + "/README.md");
  std::stringstream ss;
  ss << in.rdbuf();
  std::string readme = ss.str();
  size_t from = readme.find("## What it supports");
  ASSERT_NE(from, std::string::npos);
  std::string table = readme.substr(from, readme.find("\n## ", from + 1) - from);
  for (const PluginKind& k : pluginKinds()) {
    if (k.kind == "film" || k.kind == "renderer" || k.kind == "bump map" || k.kind == "area light")
      continue;  // one each, or named in prose
    for (const PluginSpec* p : k.plugins) {
      // Appended: GCC 12 warns falsely (-Wrestrict) on "..." + std::string.
      std::string quoted = "`";
      quoted.append(p->name).append("`");
      EXPECT_NE(table.find(quoted), std::string::npos)
          << k.kind << " '" << p->name << "' is missing from the README's table";
    }
  }
}

}  // namespace
}  // namespace candela
