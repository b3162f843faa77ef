// Each scene dialect gets its own microfacet models (parser/scene_dialect.h): pbrt-v3 scenes
// pbrt-v3's Trowbridge-Reitz materials with uroughness/vroughness and remaproughness, pbrt-v2
// scenes exactly pbrt-v2's; the detection rules, the --dialect override and plastic's coat
// Fresnel option.
#include <gtest/gtest.h>

#include <cmath>

#include "assembly/material_factory.h"
#include "materials/glass.h"
#include "materials/metal.h"
#include "materials/plastic.h"
#include "reflection/trowbridge_reitz_bxdfs.h"
#include "support/param_items.h"
#include "support/render_scene.h"

namespace candela {
namespace {

SurfaceInteraction planePoint() {
  return SurfaceInteraction(Point3f(0.3f, 0.4f, 0), Vector3f(), Point2f(0.3f, 0.4f),
                            Vector3f(0, 0, 1), Vector3f(1, 0, 0), Vector3f(0, 1, 0), Normal3f(),
                            Normal3f(), 0, false);
}

Vector3f dir(Float thetaDeg, Float phiDeg) {
  Float t = thetaDeg * kPi / 180, p = phiDeg * kPi / 180;
  return Vector3f(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
}

// One material statement in a scene that is pbrt-v3 (an Integrator statement) or not.
struct OneMaterial {
  SceneDescription scene;
  std::unique_ptr<TextureFactory> textures;
  std::vector<std::unique_ptr<Material>> owned;
  std::unique_ptr<MaterialFactory> factory;
  MemoryArena arena;

  OneMaterial(const std::string& name, std::vector<ParamItem> params, bool v3,
              CompatibilityProfile models = {}) {
    if (v3) scene.integrator.name = "path";
    MaterialDesc m;
    m.name = name;
    for (ParamItem& p : params) m.params.add(std::move(p));
    scene.materials.push_back(std::move(m));
    textures = std::make_unique<TextureFactory>(scene.textures);
    factory = std::make_unique<MaterialFactory>(scene, *textures, &owned, MaterialFactory::Used{},
                                                models);
  }
  const BSDF& bsdf() { return *factory->get(0)->getBSDF(planePoint(), arena); }
  Float f(const Vector3f& wo, const Vector3f& wi) { return bsdf().f(wo, wi)[1]; }
};

TEST(SceneDialect, DetectedFromPbrtV3Statements) {
  SceneDescription v2;
  v2.surfaceIntegrator.name = "path";
  EXPECT_EQ(detectSceneDialect(v2), SceneDialect::PbrtV2);
  EXPECT_EQ(detectSceneDialect(SceneDescription()), SceneDialect::PbrtV2);
  SceneDescription withIntegrator;
  withIntegrator.integrator.name = "path";
  EXPECT_EQ(detectSceneDialect(withIntegrator), SceneDialect::PbrtV3);
  SceneDescription withMedium;
  withMedium.media.emplace_back();
  EXPECT_EQ(detectSceneDialect(withMedium), SceneDialect::PbrtV3);
  SceneDescription withInterface;
  withInterface.shapes.emplace_back();
  withInterface.shapes.back().insideMedium = "fog";
  EXPECT_EQ(detectSceneDialect(withInterface), SceneDialect::PbrtV3);

  MaterialDesc metal;
  metal.name = "metal";
  EXPECT_FALSE(materialHasPbrtV3Parameters(metal));
  metal.params.add(test::floats("uroughness", {0.1f}));
  EXPECT_TRUE(materialHasPbrtV3Parameters(metal));
  MaterialDesc substrate;
  substrate.name = "substrate";
  substrate.params.add(test::floats("uroughness", {0.1f}));
  EXPECT_FALSE(materialHasPbrtV3Parameters(substrate));  // pbrt-v2's substrate has it too
  substrate.params.add(test::bools("remaproughness", {false}));
  EXPECT_TRUE(materialHasPbrtV3Parameters(substrate));

  EXPECT_EQ(parseSceneDialect("pbrt-v3"), SceneDialect::PbrtV3);
  EXPECT_EQ(parseSceneDialect("pbrt-v2"), SceneDialect::PbrtV2);
  EXPECT_FALSE(parseSceneDialect("v4"));
}

// How much of the mirror-direction value f keeps 30 degrees off it (a half vector tilted 15
// degrees), in the xz plane (along dp/du) and in the yz plane (along dp/dv).
struct Falloff {
  Float alongU, alongV;
};
Falloff falloff(OneMaterial& m) {
  Float u = m.f(dir(40, 0), dir(70, 180)) / m.f(dir(40, 0), dir(40, 180));
  Float v = m.f(dir(40, 90), dir(70, 270)) / m.f(dir(40, 90), dir(40, 270));
  return {u, v};
}

TEST(PbrtV3Materials, MetalUAndVRoughnessMakeItAnisotropic) {
  // uroughness 0.02 along dp/du (x), vroughness 0.3 along y: the lobe is narrow along x and
  // wide along y (alphas 0.19 and 0.86: D keeps about 13% and 95% of its peak).
  auto metal = [](Float u, Float v) {
    return OneMaterial("metal", {test::floats("uroughness", {u}), test::floats("vroughness", {v})},
                       true);
  };
  OneMaterial aniso = metal(0.02f, 0.3f), swapped = metal(0.3f, 0.02f), iso = metal(0.1f, 0.1f);
  Falloff a = falloff(aniso), s = falloff(swapped), i = falloff(iso);
  EXPECT_LT(a.alongU * 3, a.alongV);
  // Exchanging the roughnesses exchanges the axes.
  EXPECT_NEAR(s.alongU, a.alongV, 1e-4f);
  EXPECT_NEAR(s.alongV, a.alongU, 1e-4f);
  // Equal roughnesses: the same for any azimuth.
  EXPECT_NEAR(i.alongU, i.alongV, 1e-5f);
  // Given only "roughness", both axes take it.
  OneMaterial single("metal", {test::floats("roughness", {0.1f})}, true);
  Vector3f wo = dir(40, 0), wi = dir(55, 180);
  EXPECT_NEAR(single.f(wo, wi), iso.f(wo, wi), 1e-6f * iso.f(wo, wi));
}

TEST(PbrtV3Materials, RemapRoughnessChoosesBetweenRoughnessAndAlpha) {
  Vector3f wo = dir(30, 10), wi = dir(50, 200);
  for (bool remap : {true, false}) {
    OneMaterial m(
        "metal", {test::floats("roughness", {0.3f}), test::bools("remaproughness", {remap})}, true);
    // The same conductor built by hand with alpha = remapped roughness, or the roughness.
    Float alpha = remap ? roughnessToAlpha(0.3f) : 0.3f;
    TrowbridgeReitzDistribution d(alpha, alpha);
    FresnelConductor fresnel(copper::kEta, copper::kK);
    TrowbridgeReitzReflection expected(Spectrum(1), &fresnel, &d);
    EXPECT_FLOAT_EQ(m.f(wo, wi), expected.f(wo, wi)[1]) << remap;
  }
  EXPECT_NE(roughnessToAlpha(0.3f), 0.3f);  // so the two cases above differ
}

TEST(PbrtV3Materials, PbrtV2ScenesKeepPbrtV2Models) {
  // The factory's metal and plastic in a pbrt-v2 scene are exactly the pbrt-v2 materials.
  ConstantTexture<Spectrum> eta(copper::kEta), k(copper::kK), kd(Spectrum(0.25f)),
      ks(Spectrum(0.25f));
  ConstantTexture<Float> rough(0.05f);
  MetalMaterial v2Metal(&eta, &k, &rough);
  PlasticMaterial v2Plastic(&kd, &ks, &rough);
  MemoryArena arena;
  const BSDF& metal = *v2Metal.getBSDF(planePoint(), arena);
  const BSDF& plastic = *v2Plastic.getBSDF(planePoint(), arena);
  OneMaterial m2("metal", {test::floats("roughness", {0.05f})}, false);
  OneMaterial p2("plastic", {test::floats("roughness", {0.05f})}, false);
  OneMaterial m3("metal", {test::floats("roughness", {0.05f})}, true);
  OneMaterial p3("plastic", {test::floats("roughness", {0.05f})}, true);
  int differs = 0;
  for (Float t : {0.f, 20.f, 45.f, 70.f})
    for (Float t2 : {5.f, 30.f, 60.f}) {
      Vector3f wo = dir(t, 0), wi = dir(t2, 170);
      EXPECT_EQ(m2.f(wo, wi), metal.f(wo, wi)[1]);
      EXPECT_EQ(p2.f(wo, wi), plastic.f(wo, wi)[1]);
      differs += m3.f(wo, wi) != metal.f(wo, wi)[1];
      differs += p3.f(wo, wi) != plastic.f(wo, wi)[1];
    }
  EXPECT_EQ(differs, 24);  // and pbrt-v3 scenes get the other model everywhere
}

TEST(PbrtV3Materials, ExplicitDialectOverridesDetection) {
  Vector3f wo = dir(30, 0), wi = dir(35, 180);
  CompatibilityProfile v2, v3;
  v2.dialect = SceneDialect::PbrtV2;
  v3.dialect = SceneDialect::PbrtV3;
  OneMaterial detectedV3("plastic", {}, true), forcedV2("plastic", {}, true, v2);
  OneMaterial detectedV2("plastic", {}, false), forcedV3("plastic", {}, false, v3);
  EXPECT_EQ(forcedV2.f(wo, wi), detectedV2.f(wo, wi));
  EXPECT_EQ(forcedV3.f(wo, wi), detectedV3.f(wo, wi));
  EXPECT_NE(detectedV2.f(wo, wi), detectedV3.f(wo, wi));
  // In a pbrt-v2 scene a pbrt-v3-only parameter makes that material pbrt-v3's ...
  OneMaterial hinted("plastic", {test::bools("remaproughness", {true})}, false);
  EXPECT_EQ(hinted.f(wo, wi), detectedV3.f(wo, wi));
  // ... unless pbrt-v2 was chosen explicitly.
  OneMaterial hintedForced("plastic", {test::bools("remaproughness", {true})}, false, v2);
  EXPECT_EQ(hintedForced.f(wo, wi), detectedV2.f(wo, wi));
}

TEST(PbrtV3Materials, ReversedCoatFresnelBrightensPlasticAtGrazingAngles) {
  // pbrt's FresnelDielectric(1.5, 1) totally reflects past 41.8 degrees from the microfacet
  // normal; the exact coat reflects about 10% at 60 degrees.
  CompatibilityProfile reversed;
  reversed.plasticCoat = CoatFresnel::ReversedAsPbrt;
  for (bool v3 : {false, true}) {
    OneMaterial exact("plastic", {test::rgb("Kd", {0, 0, 0})}, v3);
    OneMaterial pbrt("plastic", {test::rgb("Kd", {0, 0, 0})}, v3, reversed);
    Vector3f wo = dir(60, 0), wi = dir(60, 180);  // wh = +z, 60 degrees to it
    EXPECT_GT(pbrt.f(wo, wi), 5 * exact.f(wo, wi)) << v3;
    Vector3f woN = dir(10, 0), wiN = dir(10, 180);  // near normal: both about 4%
    EXPECT_NEAR(pbrt.f(woN, wiN), exact.f(woN, wiN), 0.01f * exact.f(woN, wiN)) << v3;
  }
}

TEST(PbrtV3Materials, RoughGlassUberKtAndSubstrate) {
  // Glass with roughness refracts diffusely: one glossy component that reflects and refracts
  // (by the Fresnel term of the microfacet it draws), half of the light or more refracted;
  // without roughness, specular.
  OneMaterial rough("glass",
                    {test::floats("uroughness", {0.2f}), test::floats("vroughness", {0.2f})}, true);
  OneMaterial smooth("glass", {}, true);
  EXPECT_EQ(rough.bsdf().numComponents(kAllBxDF & ~kSpecular), 1);
  EXPECT_EQ(rough.bsdf().numComponents(kReflection | kTransmission | kGlossy), 1);
  EXPECT_EQ(rough.bsdf().numComponents(kSpecular | kReflection | kTransmission), 0);
  {
    RNG rng(3);
    std::vector<Point2f> u = stratifiedSamples2D(32, rng);
    const BSDF& b = rough.bsdf();
    Vector3f wo = dir(30, 0);
    // Refracted radiance carries 1 / eta^2: the refracted share of power is its rho times eta^2.
    EXPECT_GT(b.rho(wo, u, kAllTransmission)[1] * 1.5f * 1.5f, 0.5f);
    EXPECT_LT(b.rho(wo, u, kAllReflection)[1], 0.2f);
  }
  EXPECT_EQ(smooth.bsdf().numComponents(kTransmission | kSpecular), 1);
  EXPECT_FLOAT_EQ(rough.bsdf().eta, 1.5f);
  OneMaterial eta("glass", {test::floats("eta", {1.33f}), test::floats("index", {2})}, true);
  EXPECT_FLOAT_EQ(eta.bsdf().eta, 1.33f);  // "eta" before "index", as pbrt-v3
  // pbrt-v3's uber refracts Kt; pbrt-v2's has no such parameter.
  OneMaterial uber3("uber", {test::rgb("Kt", {0.5f, 0.5f, 0.5f})}, true);
  OneMaterial uber2("uber", {test::rgb("Kt", {0.5f, 0.5f, 0.5f})}, false);
  EXPECT_EQ(uber3.bsdf().numComponents(kTransmission | kSpecular), 1);
  EXPECT_EQ(uber2.bsdf().numComponents(kTransmission | kSpecular), 0);
  EXPECT_TRUE(uber3.factory->get(0)->maybeSpecular());
  // Substrate's u and v roughness along dp/du and dp/dv, as in metal.
  OneMaterial sub("substrate",
                  {test::rgb("Kd", {0, 0, 0}), test::floats("uroughness", {0.02f}),
                   test::floats("vroughness", {0.3f})},
                  true);
  Falloff f = falloff(sub);
  EXPECT_LT(f.alongU * 3, f.alongV);
}

// A whole scene: the same pbrt-v2 file renders the same bits with the dialect detected or given
// as pbrt-v2, and differently as pbrt-v3.
TEST(PbrtV3Materials, PbrtV2SceneRendersUnchanged) {
  const std::string scene =
      "Film \"image\" \"integer xresolution\" [16] \"integer yresolution\" [16]\n"
      "Sampler \"random\" \"integer pixelsamples\" [4]\n"
      "SurfaceIntegrator \"path\"\nLookAt 0 0 5 0 0 0 0 1 0\nCamera \"perspective\"\n"
      "WorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 1]\n"
      "Material \"plastic\" \"rgb Kd\" [0.2 0.3 0.6] \"float roughness\" [0.05]\n"
      "Shape \"sphere\"\nWorldEnd\n";
  auto render = [&](std::optional<SceneDialect> d) {
    test::TestRenderOptions o;
    o.build.compatibility.dialect = d;
    return test::renderSceneText(scene, o).film().image().data;
  };
  std::vector<float> detected = render(std::nullopt);
  EXPECT_EQ(detected, render(SceneDialect::PbrtV2));
  EXPECT_NE(detected, render(SceneDialect::PbrtV3));
}

}  // namespace
}  // namespace candela
