// Material "hair" from scene text: each way of giving the absorption parses to the BxDF it
// describes (h from the surface's v), the parameters pbrt-v3 ignores are reported unused, bad
// constants are located errors, and a cylinder of it renders finite, lit, and the same bits for 1
// and 2 threads under the path tracer.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "assembly/material_factory.h"
#include "core/error.h"
#include "materials/hair.h"
#include "reflection/hair_absorption.h"
#include "reflection/hair_bxdf.h"
#include "support/render_scene.h"

namespace candela {
namespace {

std::string cylinderScene(const std::string& hairParams, int resolution = 16) {
  return "LookAt 0 0 -6  0 0 0  0 1 0\n"
         "Camera \"perspective\" \"float fov\" [30]\n"
         "Film \"image\" \"integer xresolution\" [" +
         std::to_string(resolution) + "] \"integer yresolution\" [" + std::to_string(resolution) +
         "]\n"
         "Sampler \"random\" \"integer pixelsamples\" [4]\n"
         "Integrator \"path\" \"integer maxdepth\" [6]\n"
         "WorldBegin\n"
         "LightSource \"point\" \"point from\" [2 2 -3] \"rgb I\" [10 10 10]\n"
         "LightSource \"infinite\" \"rgb L\" [0.5 0.5 0.5]\n"
         "Material \"hair\" " +
         hairParams +
         "\n"
         "AttributeBegin\n"
         "Rotate 90 1 0 0\n"
         "Shape \"cylinder\" \"float radius\" [0.5] \"float zmin\" [-1] \"float zmax\" [1]\n"
         "AttributeEnd\n"
         "WorldEnd\n";
}

// The BxDF the material makes at a point with v = 0.8 (h = 0.6) for the statement's parameters,
// and the unused-parameter warnings of building the scene.
struct Built {
  hair::LobeSpectra attenuation;
  std::string warnings;
};

Built build(const std::string& hairParams) {
  Built out;
  test::TestRenderOptions o;
  o.build.warn = [&](const FileLoc&, const std::string& m) { out.warnings += m + "\n"; };
  test::RenderedScene r = test::buildSceneText(cylinderScene(hairParams), o.build);
  const Material* m = nullptr;
  for (const auto& owned : r.job().materials)
    if (dynamic_cast<const HairMaterial*>(owned.get())) m = owned.get();
  EXPECT_NE(m, nullptr);
  if (!m) return out;
  SurfaceInteraction si(Point3f(0, 0, 0), Vector3f(), Point2f(0.3f, 0.8f), Vector3f(0, 0, 1),
                        Vector3f(1, 0, 0), Vector3f(0, 1, 0), Normal3f(), Normal3f(), 0, false);
  MemoryArena arena;
  const BSDF* bsdf = m->getBSDF(si, arena);
  EXPECT_EQ(bsdf->numComponents(), 1);
  auto* hairBxDF = dynamic_cast<const HairBxDF*>(bsdf->component(0));
  EXPECT_NE(hairBxDF, nullptr);
  if (hairBxDF) out.attenuation = hairBxDF->attenuation(Vector3f(0.2f, 0.3f, 0.9f));
  return out;
}

void expectSameAttenuation(const hair::LobeSpectra& got, const Spectrum& sigmaA, Float eta = 1.55f,
                           Float betaM = 0.3f, Float betaN = 0.3f) {
  HairBxDF expected(0.6f, eta, sigmaA, betaM, betaN, 2);
  hair::LobeSpectra want = expected.attenuation(Vector3f(0.2f, 0.3f, 0.9f));
  for (int p = 0; p <= hair::kMaxLobe; ++p)
    for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(got[p][c], want[p][c]) << "lobe " << p;
}

TEST(HairMaterial, EachAbsorptionParameterisationParses) {
  // Nothing given: pbrt-v3's brown, eumelanin 1.3.
  expectSameAttenuation(build("").attenuation, hair::sigmaAFromConcentration(1.3f, 0));
  expectSameAttenuation(build("\"rgb sigma_a\" [0.1 0.5 2]").attenuation, Spectrum(0.1f, 0.5f, 2));
  expectSameAttenuation(build("\"rgb color\" [0.8 0.5 0.2] \"float beta_n\" [0.6]").attenuation,
                        hair::sigmaAFromReflectance(Spectrum(0.8f, 0.5f, 0.2f), 0.6f), 1.55f, 0.3f,
                        0.6f);
  // One melanin given: the other is 0, not the default.
  expectSameAttenuation(build("\"float pheomelanin\" [0.7]").attenuation,
                        hair::sigmaAFromConcentration(0, 0.7f));
  expectSameAttenuation(
      build("\"float eumelanin\" [0.3] \"float pheomelanin\" [0.2] \"float eta\" [1.4]")
          .attenuation,
      hair::sigmaAFromConcentration(0.3f, 0.2f), 1.4f);
}

TEST(HairMaterial, OverriddenAbsorptionParametersAreReportedUnused) {
  // pbrt-v3 takes sigma_a over color over the melanins.
  Built b = build("\"rgb sigma_a\" [1 1 1] \"rgb color\" [0.5 0.5 0.5] \"float eumelanin\" [2]");
  expectSameAttenuation(b.attenuation, Spectrum(1));
  EXPECT_NE(b.warnings.find("color"), std::string::npos) << b.warnings;
  EXPECT_NE(b.warnings.find("eumelanin"), std::string::npos) << b.warnings;
  Built c = build("\"rgb color\" [0.5 0.5 0.5] \"float pheomelanin\" [2]");
  EXPECT_NE(c.warnings.find("pheomelanin"), std::string::npos) << c.warnings;
  EXPECT_EQ(c.warnings.find("color"), std::string::npos) << c.warnings;
}

TEST(HairMaterial, BadConstantsAreLocatedErrors) {
  // The parameter alone on line 4 of the scene; the error names it and points there.
  for (const char* bad :
       {"\"rgb sigma_a\" [0.1 -0.2 0.3]", "\"rgb color\" [0.5 1.5 0.5]", "\"float eumelanin\" [-1]",
        "\"float pheomelanin\" [-0.5]", "\"float eta\" [0.9]", "\"float beta_m\" [0]",
        "\"float beta_m\" [1.5]", "\"float beta_n\" [-0.1]", "\"float beta_n\" [2]"}) {
    SCOPED_TRACE(bad);
    std::string name = std::string(bad).substr(std::string(bad).find(' ') + 1);
    name = name.substr(0, name.find('"'));
    std::string scene =
        std::string("Film \"image\" \"integer xresolution\" [4] \"integer yresolution\" [4]\n") +
        "WorldBegin\nMaterial \"hair\"\n  " + bad +
        "\nShape \"sphere\" \"float radius\" [0.5]\nWorldEnd\n";
    try {
      test::buildSceneText(scene);
      ADD_FAILURE() << "no error";
    } catch (const SceneError& e) {
      EXPECT_EQ(e.location().line, 4) << e.what();
      EXPECT_EQ(e.location().column, 3) << e.what();
      EXPECT_NE(std::string(e.what()).find("\"" + name + "\""), std::string::npos) << e.what();
    }
  }
}

TEST(HairMaterial, CylinderRendersFiniteAndDeterministic) {
  for (const char* params : {"", "\"rgb color\" [0.9 0.6 0.3]", "\"rgb sigma_a\" [0 0 0]",
                             "\"float beta_m\" [0.1] \"float beta_n\" [1] \"float alpha\" [5]"}) {
    SCOPED_TRACE(params);
    test::TestRenderOptions one, two;
    one.build.nThreads = one.render.nThreads = 1;
    two.build.nThreads = two.render.nThreads = 2;
    ImageBuffer a = test::renderSceneText(cylinderScene(params), one).film().image();
    ImageBuffer b = test::renderSceneText(cylinderScene(params), two).film().image();
    ASSERT_EQ(a.data.size(), b.data.size());
    double sum = 0;
    for (float v : a.data) {
      ASSERT_TRUE(std::isfinite(v));
      ASSERT_GE(v, 0);
      sum += v;
    }
    EXPECT_GT(sum, 0);
    EXPECT_EQ(0, std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)));
  }
}

}  // namespace
}  // namespace candela
