// pbrt-v3 media in harder settings — inside a glass sphere (the interface is the glass), in an
// object instance, on a moving shape — render finite and the same bits for 1 and 2 threads; bad
// media input is a located SceneError; integrators that ignore media say so, naming the
// statement; a scene without media carries none.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <stdexcept>

#include "accel/primitive.h"
#include "core/error.h"
#include "support/render_scene.h"

namespace candela {
namespace {

std::string header(const std::string& integrator) {
  return "LookAt 0 0.5 -4  0 0 0  0 1 0\n"
         "Camera \"perspective\" \"float fov\" [40] \"float shutteropen\" [0] "
         "\"float shutterclose\" [1]\n"
         "Film \"image\" \"integer xresolution\" [24] \"integer yresolution\" [24]\n"
         "Sampler \"random\" \"integer pixelsamples\" [8]\n" +
         integrator +
         "\nWorldBegin\n"
         "LightSource \"infinite\" \"rgb L\" [0.3 0.3 0.4]\n"
         "LightSource \"point\" \"point from\" [2 3 -2] \"rgb I\" [10 10 10]\n"
         "AttributeBegin\n"
         "AreaLightSource \"diffuse\" \"rgb L\" [4 4 4]\n"
         "Translate 0 2.5 0\n"
         "Shape \"sphere\" \"float radius\" [0.3]\n"
         "AttributeEnd\n"
         "Material \"matte\"\n"
         "Shape \"trianglemesh\" \"point P\" [-5 -1 -5  5 -1 -5  5 -1 5  -5 -1 5] "
         "\"integer indices\" [0 1 2 0 2 3]\n"
         "MakeNamedMedium \"smoke\" \"string type\" \"heterogeneous\" \"integer nx\" [2] "
         "\"integer ny\" [2] \"integer nz\" [2] \"float density\" [0.2 1 2 0.5 1 3 0.1 2] "
         "\"point p0\" [-1 -1 -1] \"point p1\" [1 1 1] \"rgb sigma_s\" [2 2 2] "
         "\"rgb sigma_a\" [0.2 0.3 0.4] \"float g\" [0.3]\n"
         "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\" \"rgb sigma_s\" [1 1 1] "
         "\"rgb sigma_a\" [0.1 0.1 0.1]\n";
}

const char* kGlassSphere =
    "AttributeBegin\n"
    "MediumInterface \"smoke\" \"\"\n"
    "Material \"glass\"\n"
    "Shape \"sphere\" \"float radius\" [1]\n"
    "AttributeEnd\n";

const char* kInstances =
    "ObjectBegin \"puff\"\n"
    "MediumInterface \"fog\" \"\"\n"
    "Material \"none\"\n"
    "Shape \"sphere\" \"float radius\" [0.5]\n"
    "ObjectEnd\n"
    "AttributeBegin\nTranslate -1 0 0\nObjectInstance \"puff\"\nAttributeEnd\n"
    "AttributeBegin\nTranslate 1 0 0\nObjectInstance \"puff\"\nAttributeEnd\n";

const char* kMovingInterface =
    "AttributeBegin\n"
    "ActiveTransform EndTime\nTranslate 0.5 0 0\nActiveTransform All\n"
    "MediumInterface \"fog\" \"\"\n"
    "Material \"none\"\n"
    "Shape \"sphere\" \"float radius\" [0.8]\n"
    "AttributeEnd\n";

// text with the first `from` replaced by `to`.
std::string replaced(const std::string& text, const std::string& from, const std::string& to) {
  size_t at = text.find(from);
  if (at == std::string::npos) throw std::logic_error("no '" + from + "' in the scene");
  return text.substr(0, at) + to + text.substr(at + from.size());
}

ImageBuffer render(const std::string& scene, int threads) {
  test::TestRenderOptions o;
  o.build.seed = 3;
  o.render.nThreads = threads;
  return test::renderSceneText(scene, o).film().image();
}

void expectFiniteAndDeterministic(const std::string& world) {
  std::string scene =
      header("Integrator \"volpath\" \"integer maxdepth\" [20]") + world + "WorldEnd\n";
  ImageBuffer one = render(scene, 1), two = render(scene, 2);
  ASSERT_EQ(one.data.size(), two.data.size());
  EXPECT_EQ(0, std::memcmp(one.data.data(), two.data.data(), one.data.size() * sizeof(float)));
  double sum = 0;
  for (float v : one.data) {
    ASSERT_TRUE(std::isfinite(v));
    sum += v;
  }
  EXPECT_GT(sum, 0);
}

TEST(MediaScenes, InsideAGlassSphere) { expectFiniteAndDeterministic(kGlassSphere); }
TEST(MediaScenes, InObjectInstances) { expectFiniteAndDeterministic(kInstances); }
TEST(MediaScenes, UnderMotionBlur) { expectFiniteAndDeterministic(kMovingInterface); }

// The medium changes the picture (so the scenes above do test media): volpath with the glass
// sphere's smoke differs from the same sphere without a MediumInterface.
TEST(MediaScenes, TheMediumMatters) {
  std::string withSmoke = header("Integrator \"volpath\"") + kGlassSphere + "WorldEnd\n";
  std::string without = replaced(withSmoke, "MediumInterface \"smoke\" \"\"\n", "");
  ImageBuffer a = render(withSmoke, 1), b = render(without, 1);
  double diff = 0;
  for (size_t i = 0; i < a.data.size(); ++i) diff += std::abs(a.data[i] - b.data[i]);
  EXPECT_GT(diff / double(a.data.size()), 0.01);
}

void expectLocatedError(const std::string& scene, int line, const std::string& needle) {
  SCOPED_TRACE(needle);
  try {
    test::buildSceneText(scene);
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.location().line, line) << e.what();
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

std::string mediumScene(const std::string& medium, const std::string& interfaceName = "m") {
  return "Film \"image\" \"integer xresolution\" [4] \"integer yresolution\" [4]\n"
         "Integrator \"volpath\"\n"
         "WorldBegin\n"
         "MakeNamedMedium \"m\" \"string type\" " +
         medium +
         "\n"  // line 4
         "MediumInterface \"" +
         interfaceName +
         "\" \"\"\n"  // line 5
         "Material \"none\"\n"
         "Shape \"sphere\" \"float radius\" [0.5]\n"  // line 7
         "WorldEnd\n";
}

TEST(MediaScenes, BadInputIsALocatedError) {
  expectLocatedError(mediumScene("\"homogeneous\" \"rgb sigma_a\" [-1 0 0]"), 4, "sigma_a");
  expectLocatedError(mediumScene("\"homogeneous\" \"rgb sigma_s\" [0 -2 0]"), 4, "sigma_s");
  expectLocatedError(mediumScene("\"homogeneous\" \"float g\" [1]"), 4,
                     "\"g\" must be within (-1, 1) (got 1)");
  expectLocatedError(mediumScene("\"homogeneous\" \"float scale\" [-1]"), 4, "scale");
  expectLocatedError(mediumScene("\"heterogeneous\" \"integer nx\" [2] \"float density\" [1 2 3]"),
                     4, "density");
  expectLocatedError(mediumScene("\"heterogeneous\" \"float density\" [-1]"), 4, "density");
  expectLocatedError(mediumScene("\"heterogeneous\" \"float density\" [1] \"point p0\" [0 0 0] "
                                 "\"point p1\" [1 0 1]"),
                     4, "p1");
  expectLocatedError(mediumScene("\"cloudy\""), 4, "cloudy");
  expectLocatedError(mediumScene("\"homogeneous\"", "nonesuch"), 5, "nonesuch");
}

struct Captured {
  std::vector<std::string> warnings;
  BuildOptions options;
  Captured() {
    options.warn = [this](const FileLoc& loc, const std::string& message) {
      warnings.push_back(loc.str() + ": " + message);
    };
  }
  int count(const std::string& needle) const {
    int n = 0;
    for (const auto& w : warnings) n += w.find(needle) != std::string::npos;
    return n;
  }
};

TEST(MediaScenes, IntegratorsThatIgnoreMediaSaySo) {
  std::string scene = mediumScene("\"homogeneous\"");
  for (const char* integrator : {"SurfaceIntegrator \"path\"", "SurfaceIntegrator \"whitted\""}) {
    std::string s = replaced(scene, "Integrator \"volpath\"", integrator);
    Captured c;
    test::buildSceneText(s, c.options);
    ASSERT_EQ(c.count("ignores participating media"), 1) << integrator;
    EXPECT_EQ(c.count("test.pbrt:4:"), 1);  // at the MakeNamedMedium
    EXPECT_EQ(c.count("test.pbrt:5:"), 1);  // and it names the MediumInterface
  }
  Captured c;
  auto built = test::buildSceneText(scene, c.options);
  EXPECT_EQ(c.count("ignores"), 0);
  EXPECT_TRUE(built.job().scene->media().present);
  EXPECT_EQ(built.job().stats.namedMedia, 1);
  EXPECT_EQ(built.job().stats.mediumInterfaces, 1);
}

TEST(MediaScenes, UnusedMediaAreReportedAndNotBuilt) {
  std::string scene =
      replaced(mediumScene("\"homogeneous\""), "MediumInterface \"m\" \"\"\n", "\n");
  Captured c;
  auto built = test::buildSceneText(scene, c.options);
  EXPECT_EQ(c.count("test.pbrt:4:"), 1);
  EXPECT_EQ(c.count("never used"), 1);
  EXPECT_FALSE(built.job().scene->media().present);
}

TEST(MediaScenes, UnusedParametersOfAMediumAreReported) {
  Captured c;
  test::buildSceneText(mediumScene("\"homogeneous\" \"float sigma_ss\" [1]"), c.options);
  EXPECT_EQ(c.count("sigma_ss"), 1);
  EXPECT_EQ(c.count("test.pbrt:4:"), 1);
  EXPECT_EQ(c.count("\"string type\""), 0);
}

TEST(MediaScenes, ASceneWithoutMediaCarriesNone) {
  auto built = test::buildSceneText(test::cornellBoxText(8));
  const RenderJob& job = built.job();
  EXPECT_FALSE(job.scene->media().present);
  EXPECT_EQ(job.scene->media().camera, nullptr);
  for (const Primitive& p : job.geometry.primitives) EXPECT_EQ(p.mediumInterface, nullptr);
  EXPECT_EQ(job.stats.namedMedia, 0);
  EXPECT_NE(job.stats.report().find("named media  0 (interfaces 0)"), std::string::npos);
}

}  // namespace
}  // namespace candela
