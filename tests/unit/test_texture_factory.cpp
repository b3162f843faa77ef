// TextureFactory: classes and parameters, references between textures, laziness, one load per
// image, and the errors a scene can provoke.
#include <gtest/gtest.h>

#include "assembly/texture_factory.h"
#include "support/param_items.h"
#include "support/render_scene.h"
#include "support/scene_error_of.h"
#include "textures/dots.h"
#include "textures/image_texture.h"

using namespace candela;

namespace {

// Relative image paths resolve against the directory of the scene file the parameter is in.
ParamItem filename(const std::string& path) {
  return test::strings("filename", {path}, FileLoc{"/scenes/a/scene.pbrt", 9, 5});
}

TextureDesc tex(const std::string& name, const std::string& type, const std::string& cls,
                std::vector<ParamItem> items = {}, int line = 3) {
  TextureDesc d;
  d.textureName = name;
  d.type = type;
  d.name = cls;
  d.loc = FileLoc{"/scenes/a/scene.pbrt", line, 1};
  for (auto& i : items) d.params.add(i);
  return d;
}

using test::sceneErrorOf;

const FileLoc kMatLoc{"/scenes/a/scene.pbrt", 20, 1};

// An image loader that makes a w x h grey image of value `value` and counts its calls.
struct FakeLoader {
  std::vector<std::pair<std::string, std::string>> calls;
  Float value = 0.5f;
  ImageLoader loader() {
    return [this](const std::string& path, const std::string& colorSpace) {
      calls.emplace_back(path, colorSpace);
      if (path.find("missing") != std::string::npos)
        throw FileError(path, "cannot read texture image: no such file");
      ImageBuffer img(4, 2, {"R", "G", "B"});
      for (float& v : img.data) v = value;
      return img;
    };
  }
};

SurfaceInteraction atUV(Float u, Float v) {
  SurfaceInteraction si;
  si.uv = Point2f(u, v);
  si.p = Point3f(u, v, 0);
  return si;
}

}  // namespace

TEST(TextureFactory, ConstantsAndReferences) {
  std::vector<TextureDesc> descs = {
      tex("c", "spectrum", "constant", {test::rgb("value", {0.1f, 0.2f, 0.3f})}),
      tex("f", "float", "constant", {test::floats("value", {0.25f})}),
      tex("unused", "spectrum", "checkerboard"),
  };
  TextureFactory f(descs);
  const Texture<Spectrum>* kd =
      f.spectrum(test::paramSet({test::texture("Kd", "c")}), "Kd", Spectrum(1), kMatLoc);
  const Texture<Spectrum>* again =
      f.spectrum(test::paramSet({test::texture("Kr", "c")}), "Kr", Spectrum(1), kMatLoc);
  EXPECT_EQ(kd, again);  // created once
  EXPECT_EQ(kd->evaluate(atUV(0, 0)), Spectrum(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(f.scalar(test::paramSet({test::texture("sigma", "f")}), "sigma", 0, kMatLoc)
                ->evaluate(atUV(0, 0)),
            0.25f);
  EXPECT_EQ(f.texturesCreated(), 2);  // "unused" never made
  // No reference: a constant of the parameter's value, or the default.
  EXPECT_EQ(f.scalar(test::paramSet({test::floats("sigma", {3})}), "sigma", 0, kMatLoc)
                ->evaluate(atUV(0, 0)),
            3.f);
  EXPECT_EQ(f.spectrum(ParamSet(), "Kd", Spectrum(0.5f), kMatLoc)->evaluate(atUV(0, 0)),
            Spectrum(0.5f));
  EXPECT_EQ(f.texturesCreated(), 2);
}

TEST(TextureFactory, EveryClassWithItsDefaults) {
  std::vector<TextureDesc> descs = {
      tex("scale", "float", "scale"),  // 1 * 1
      tex("mix", "float", "mix"),      // (1 - .5) 0 + .5 * 1
      tex("bilerp", "float", "bilerp"),
      tex("uv", "spectrum", "uv"),
      tex("checks", "float", "checkerboard"),
      tex("checks3", "float", "checkerboard", {test::ints("dimension", {3})}),
      tex("dots", "float", "dots"),
      tex("fbm", "float", "fbm"),
      tex("wrinkled", "spectrum", "wrinkled"),
      tex("windy", "float", "windy"),
      tex("marble", "spectrum", "marble"),
      tex("constant", "float", "constant"),
  };
  TextureFactory f(descs);
  auto scalar = [&](const std::string& name, Float u, Float v) {
    return f.scalar(test::paramSet({test::texture("x", name)}), "x", 0, kMatLoc)
        ->evaluate(atUV(u, v));
  };
  EXPECT_EQ(scalar("scale", .3f, .3f), 1.f);
  EXPECT_EQ(scalar("mix", .3f, .3f), 0.5f);
  EXPECT_FLOAT_EQ(scalar("bilerp", .3f, .6f), .6f);  // v00 0, v01 1, v10 0, v11 1: t
  EXPECT_EQ(scalar("checks", .5f, .5f), 1.f);        // tex1 = 1 on even checks
  EXPECT_EQ(scalar("checks", 1.5f, .5f), 0.f);
  EXPECT_EQ(scalar("checks3", 1.5f, .5f), 0.f);
  EXPECT_EQ(scalar("constant", .5f, .5f), 1.f);
  for (const char* name : {"dots", "fbm", "windy"})
    EXPECT_TRUE(std::isfinite(scalar(name, 2.3f, 4.1f))) << name;
  auto spectrum = [&](const std::string& name, Float u, Float v) {
    return f.spectrum(test::paramSet({test::texture("x", name)}), "x", Spectrum(0), kMatLoc)
        ->evaluate(atUV(u, v));
  };
  EXPECT_EQ(spectrum("uv", 1.25f, 0.5f), Spectrum(0.25f, 0.5f, 0));
  EXPECT_TRUE(spectrum("marble", 0.3f, 0.7f).isFinite());
  EXPECT_TRUE(spectrum("wrinkled", 0.3f, 0.7f).isFinite());
  EXPECT_EQ(f.texturesCreated(), int(descs.size()));
}

TEST(TextureFactory, TexturesNameEarlierTexturesOnly) {
  // "a" is redefined as twice the earlier "a": the reference inside means the definition before.
  std::vector<TextureDesc> descs = {
      tex("a", "float", "constant", {test::floats("value", {0.25f})}, 1),
      tex("two", "float", "constant", {test::floats("value", {2})}, 2),
      tex("a", "float", "scale", {test::texture("tex1", "a"), test::texture("tex2", "two")}, 3),
      tex("m", "float", "mix", {test::texture("tex1", "a"), test::texture("amount", "two")}, 4),
  };
  TextureFactory f(descs);
  EXPECT_EQ(
      f.scalar(test::paramSet({test::texture("x", "a")}), "x", 0, kMatLoc)->evaluate(atUV(0, 0)),
      0.5f);
  // m: (1 - 2) * a + 2 * tex2 default 1 = -0.5 + 2.
  EXPECT_EQ(
      f.scalar(test::paramSet({test::texture("x", "m")}), "x", 0, kMatLoc)->evaluate(atUV(0, 0)),
      1.5f);
  EXPECT_EQ(f.texturesCreated(), 4);

  // A texture cannot name itself or anything defined after it, so cycles cannot exist.
  std::vector<TextureDesc> cyclic = {
      tex("p", "float", "scale", {test::texture("tex1", "q")}, 1),
      tex("q", "float", "scale", {test::texture("tex1", "p")}, 2),
  };
  TextureFactory g(cyclic);
  std::string e =
      sceneErrorOf([&] { g.scalar(test::paramSet({test::texture("x", "p")}), "x", 0, kMatLoc); });
  EXPECT_NE(e.find("no float texture named 'q' defined before this texture"), std::string::npos)
      << e;
}

TEST(TextureFactory, Errors) {
  std::vector<TextureDesc> descs = {
      tex("f", "float", "constant"),
      tex("weird", "spectrum", "plaid", {}, 7),
      tex("uvf", "float", "uv", {}, 8),
      tex("marblef", "float", "marble", {}, 9),
      tex("cube", "float", "checkerboard", {test::ints("dimension", {4})}),
      tex("aa", "float", "checkerboard", {test::strings("aamode", {"fancy"})}),
      tex("map", "float", "bilerp", {test::strings("mapping", {"cubic"})}),
  };
  TextureFactory f(descs);
  auto useS = [&](const std::string& name) {
    return sceneErrorOf([&] {
      f.spectrum(test::paramSet({test::texture("Kd", name)}), "Kd", Spectrum(1), kMatLoc);
    });
  };
  auto useF = [&](const std::string& name) {
    return sceneErrorOf(
        [&] { f.scalar(test::paramSet({test::texture("x", name)}), "x", 0, kMatLoc); });
  };
  std::string e = useS("weird");
  EXPECT_NE(e.find("scene.pbrt:7:1"), std::string::npos) << e;
  EXPECT_NE(e.find("unknown texture 'plaid'"), std::string::npos) << e;
  for (const char* known : {"checkerboard", "imagemap", "marble", "wrinkled", "windy", "bilerp"})
    EXPECT_NE(e.find(known), std::string::npos) << known;
  e = useS("f");
  EXPECT_NE(e.find("'f' is a float texture"), std::string::npos) << e;
  EXPECT_NE(e.find("needs a spectrum texture"), std::string::npos) << e;
  e = useS("nothing");
  EXPECT_NE(e.find("no spectrum texture named 'nothing'"), std::string::npos) << e;
  EXPECT_NE(useF("uvf").find("spectrum textures only"), std::string::npos);
  EXPECT_NE(useF("marblef").find("spectrum textures only"), std::string::npos);
  EXPECT_NE(useF("cube").find("\"dimension\" must be within [2, 3] (got 4)"), std::string::npos);
  EXPECT_NE(
      useF("aa").find("\"aamode\" must be one of closedform, supersample, none (got \"fancy\")"),
      std::string::npos);
  EXPECT_NE(useF("map").find("unknown texture mapping 'cubic'"), std::string::npos);
}

TEST(TextureFactory, UnusedTextureParametersAreReported) {
  std::vector<TextureDesc> descs = {
      tex("c", "float", "constant", {test::floats("value", {1}), test::floats("valeu", {2})})};
  std::vector<std::string> warnings;
  TextureFactory f(descs, {}, [&](const FileLoc&, const std::string& m) { warnings.push_back(m); });
  f.scalar(test::paramSet({test::texture("x", "c")}), "x", 0, kMatLoc);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("\"float valeu\" of texture 'c'"), std::string::npos) << warnings[0];
}

TEST(TextureFactory, ImagesAreLoadedOnceAndOnlyWhenUsed) {
  FakeLoader fake;
  std::vector<TextureDesc> descs = {
      tex("a", "spectrum", "imagemap", {filename("tex/wood.png")}),
      tex("b", "spectrum", "imagemap",
          {filename("tex/../tex/wood.png"), test::floats("uscale", {4})}),
      tex("c", "spectrum", "imagemap",
          {filename("/abs/wood.png"), test::strings("wrap", {"clamp"})}),
      tex("clamped", "spectrum", "imagemap",
          {filename("tex/wood.png"), test::strings("wrap", {"clamp"})}),
      tex("grey", "float", "imagemap", {filename("tex/wood.png")}),
      tex("linear", "spectrum", "imagemap",
          {filename("tex/wood.png"), test::strings("colorspace", {"raw"})}),
      tex("never", "spectrum", "imagemap", {filename("missing.png")}),
  };
  TextureFactory f(descs, fake.loader());
  auto use = [&](const std::string& name) {
    return f.spectrum(test::paramSet({test::texture("Kd", name)}), "Kd", Spectrum(1), kMatLoc);
  };
  const Texture<Spectrum>* a = use("a");
  const Texture<Spectrum>* b = use("b");
  ASSERT_EQ(fake.calls.size(), 1u);
  // Relative to the scene file's directory, normalized, with the default colour space rule.
  EXPECT_EQ(fake.calls[0], std::make_pair(std::string("/scenes/a/tex/wood.png"), std::string()));
  // Same file, wrap, scale and gamma: the same MIP map.
  EXPECT_EQ(&dynamic_cast<const ImageTexture<Spectrum>*>(a)->mipmap(),
            &dynamic_cast<const ImageTexture<Spectrum>*>(b)->mipmap());
  EXPECT_EQ(f.mipmapsBuilt(), 1);
  use("c");
  EXPECT_EQ(fake.calls.back().first, "/abs/wood.png");
  use("clamped");  // another pyramid, no new load
  f.scalar(test::paramSet({test::texture("x", "grey")}), "x", 0, kMatLoc)
      ->evaluate(atUV(0.3f, 0.3f));
  EXPECT_EQ(f.mipmapsBuilt(), 4);
  EXPECT_EQ(fake.calls.size(), 2u);
  use("linear");  // another colour space: another load
  ASSERT_EQ(fake.calls.size(), 3u);
  EXPECT_EQ(fake.calls.back().second, "raw");
  EXPECT_EQ(f.imagesLoaded(), 3);
  EXPECT_NEAR(a->evaluate(atUV(0.3f, 0.6f))[1], 0.5f, 1e-6f);
  // "never" is never used, so its missing file never matters.
  for (const auto& call : fake.calls) EXPECT_EQ(call.first.find("missing"), std::string::npos);
}

TEST(TextureFactory, ImageErrorsNameThePath) {
  FakeLoader fake;
  std::vector<TextureDesc> descs = {
      tex("gone", "spectrum", "imagemap", {filename("missing.png")}, 12),
      tex("nofile", "spectrum", "imagemap", {}, 13),
      tex("wrap", "spectrum", "imagemap", {filename("x.png"), test::strings("wrap", {"mirror"})},
          14),
  };
  TextureFactory f(descs, fake.loader());
  auto use = [&](const std::string& name) {
    return sceneErrorOf([&] {
      f.spectrum(test::paramSet({test::texture("Kd", name)}), "Kd", Spectrum(1), kMatLoc);
    });
  };
  std::string e = use("gone");
  EXPECT_NE(e.find("scene.pbrt:12:1"), std::string::npos) << e;
  EXPECT_NE(e.find("/scenes/a/missing.png"), std::string::npos) << e;
  EXPECT_NE(e.find("no such file"), std::string::npos) << e;
  EXPECT_NE(use("nofile").find("needs a \"string filename\""), std::string::npos);
  EXPECT_NE(use("wrap").find("\"wrap\" must be one of repeat, black, clamp (got \"mirror\")"),
            std::string::npos);
  EXPECT_EQ(fake.calls.size(), 1u);  // the parameter errors came before any reading

  TextureFactory noReader(descs);
  e = sceneErrorOf([&] {
    noReader.spectrum(test::paramSet({test::texture("Kd", "gone")}), "Kd", Spectrum(1), kMatLoc);
  });
  EXPECT_NE(e.find("no image reader"), std::string::npos) << e;
  EXPECT_NE(e.find("/scenes/a/missing.png"), std::string::npos) << e;
}

TEST(TextureFactory, ImageScaleAndGamma) {
  FakeLoader fake;
  fake.value = 0.25f;
  std::vector<TextureDesc> descs = {
      tex("g", "float", "imagemap",
          {filename("g.exr"), test::floats("scale", {2}), test::floats("gamma", {2}),
           test::strings("trilinear", {"x"})}),
  };
  // "trilinear" of the wrong type is an error at its own location.
  TextureFactory bad(descs, fake.loader());
  EXPECT_NE(sceneErrorOf([&] {
              bad.scalar(test::paramSet({test::texture("x", "g")}), "x", 0, kMatLoc);
            }).find("trilinear"),
            std::string::npos);
  descs[0].params = ParamSet();
  descs[0].params.add(filename("g.exr"));
  descs[0].params.add(test::floats("scale", {2}));
  descs[0].params.add(test::floats("gamma", {2}));
  TextureFactory f(descs, fake.loader());
  EXPECT_FLOAT_EQ(f.scalar(test::paramSet({test::texture("x", "g")}), "x", 0, kMatLoc)
                      ->evaluate(atUV(0.3f, 0.3f)),
                  0.25f);  // (2 * 0.25)^2
}

// With bindings (SceneBuilder's graphics-state scoping), a name means the definition bound at the
// statement, not the latest one; a name bound to nothing is an error at the parameter.
TEST(TextureFactory, BindingsChooseTheDefinitionInEffect) {
  std::vector<TextureDesc> descs = {
      tex("m", "float", "constant", {test::floats("value", {0.1f})}, 1),
      tex("m", "float", "constant", {test::floats("value", {0.2f})}, 2),
      tex("s", "float", "scale", {test::texture("tex1", "m")}, 3),
  };
  descs[2].textures = TextureBindings{{{"m", 0}}, {}};
  TextureFactory f(descs);
  ParamSet uses = test::paramSet({test::texture("x", "m")});
  TextureBindings first{{{"m", 0}}, {}}, second{{{"m", 1}}, {}};
  EXPECT_FLOAT_EQ(f.scalar(uses, "x", 0, kMatLoc, &first)->evaluate(atUV(0, 0)), 0.1f);
  EXPECT_FLOAT_EQ(f.scalar(uses, "x", 0, kMatLoc, &second)->evaluate(atUV(0, 0)), 0.2f);
  // Without bindings: the latest definition.
  EXPECT_FLOAT_EQ(f.scalar(uses, "x", 0, kMatLoc)->evaluate(atUV(0, 0)), 0.2f);
  // "s" names the "m" bound at its statement, though a later one exists.
  TextureBindings s{{{"s", 2}}, {}};
  EXPECT_FLOAT_EQ(f.scalar(test::paramSet({test::texture("x", "s")}), "x", 0, kMatLoc, &s)
                      ->evaluate(atUV(0, 0)),
                  0.1f);
  TextureBindings none;
  std::string e = sceneErrorOf([&] {
    f.scalar(test::paramSet({test::texture("x", "m", FileLoc{"/scenes/a/scene.pbrt", 30, 9})}), "x",
             0, kMatLoc, &none);
  });
  EXPECT_NE(e.find("scene.pbrt:30:9"), std::string::npos) << e;
  EXPECT_NE(e.find("no float texture named 'm' in effect at this statement"), std::string::npos)
      << e;
}

// pbrt-v2 and v3 give "inside" to the space between the dots and "outside" to the dots.
TEST(TextureFactory, DotsUsePbrtsParameterRoles) {
  std::vector<TextureDesc> descs = {tex(
      "d", "float", "dots", {test::floats("inside", {0.25f}), test::floats("outside", {0.75f})})};
  TextureFactory f(descs);
  const Texture<Float>* d = f.scalar(test::paramSet({test::texture("x", "d")}), "x", 0, kMatLoc);
  int inDots = 0, between = 0;
  for (Float s = 0; s < 8; s += 0.05f)
    for (Float t = 0; t < 8; t += 0.05f) {
      bool dot = insidePolkaDot(s, t);
      EXPECT_EQ(d->evaluate(atUV(s, t)), dot ? 0.75f : 0.25f) << s << " " << t;
      (dot ? inDots : between)++;
    }
  EXPECT_GT(inDots, 100);
  EXPECT_GT(between, 100);
}

// Solid textures use the CTM at the Texture statement as their world-to-texture transform, as
// pbrt-v2 and v3 do: a Scale 2 there makes the pattern twice as fine.
TEST(TextureFactory, SolidTexturesUseTheCtmAsWorldToTexture) {
  std::vector<TextureDesc> descs = {
      tex("c", "float", "checkerboard",
          {test::ints("dimension", {3}), test::strings("aamode", {"none"})})};
  descs[0].textureToWorld = scale(2, 2, 2);
  TextureFactory f(descs);
  const Texture<Float>* c = f.scalar(test::paramSet({test::texture("x", "c")}), "x", 0, kMatLoc);
  auto at = [&](Float x) {
    SurfaceInteraction si;
    si.p = Point3f(x, 0.1f, 0.1f);
    return c->evaluate(si);
  };
  EXPECT_EQ(at(0.3f), 1.f);  // 2x = 0.6: the tex1 cell
  EXPECT_EQ(at(0.7f), 0.f);  // 2x = 1.4: the next cell, tex2
  EXPECT_EQ(at(1.2f), 1.f);  // 2x = 2.4
}

// Image textures honour "string mapping"; the planar mapping projects the world-space point
// (pbrt-v2, v3), whatever the transform at the Texture statement.
TEST(TextureFactory, ImageTexturesHonourTheMapping) {
  // Two texels: 0 on the left, 1 on the right.
  ImageLoader twoTexels = [](const std::string&, const std::string&) {
    ImageBuffer img(2, 1, {"R", "G", "B"});
    for (int c = 0; c < 3; ++c) img.at(0, 0, c) = 0, img.at(1, 0, c) = 1;
    return img;
  };
  std::vector<TextureDesc> descs = {
      tex("uv", "float", "imagemap", {filename("two.exr")}),
      tex("planar", "float", "imagemap",
          {filename("two.exr"), test::strings("mapping", {"planar"}),
           test::vectors("v1", {1, 0, 0}), test::vectors("v2", {0, 1, 0}),
           test::floats("udelta", {0.5f})}),
  };
  descs[1].textureToWorld = scale(2, 2, 2);
  TextureFactory f(descs, twoTexels);
  SurfaceInteraction si;
  si.uv = Point2f(0.25f, 0.5f);    // the left texel's centre
  si.p = Point3f(0.25f, 0.5f, 0);  // planar: s = 0.25 + 0.5, the right texel's centre
  EXPECT_NEAR(f.scalar(test::paramSet({test::texture("x", "uv")}), "x", 0, kMatLoc)->evaluate(si),
              0.f, 1e-6f);
  EXPECT_NEAR(
      f.scalar(test::paramSet({test::texture("x", "planar")}), "x", 0, kMatLoc)->evaluate(si), 1.f,
      1e-6f);
}

// pbrt-v3's "bool gamma": true reads the numbers as sRGB-encoded, false as linear, whatever the
// pixel type; an explicit "string colorspace" wins; pbrt-v2's "float gamma" stays an exponent.
TEST(TextureFactory, ImageGammaAsPbrtV3Bool) {
  FakeLoader fake;
  std::vector<TextureDesc> descs = {
      tex("on", "spectrum", "imagemap", {filename("g.exr"), test::bools("gamma", {true})}),
      tex("off", "spectrum", "imagemap", {filename("g.png"), test::bools("gamma", {false})}),
      tex("named", "spectrum", "imagemap",
          {filename("g.png"), test::bools("gamma", {true}), test::strings("colorspace", {"raw"})}),
      tex("absent", "spectrum", "imagemap", {filename("g.png")}),
  };
  std::vector<std::string> warnings;
  TextureFactory f(descs, fake.loader(),
                   [&](const FileLoc&, const std::string& m) { warnings.push_back(m); });
  for (const char* name : {"on", "off", "named", "absent"})
    f.spectrum(test::paramSet({test::texture("Kd", name)}), "Kd", Spectrum(1), kMatLoc);
  ASSERT_EQ(fake.calls.size(), 4u);
  EXPECT_EQ(fake.calls[0].second, kSrgbEncoded);
  EXPECT_EQ(fake.calls[1].second, kStoredLinear);
  EXPECT_EQ(fake.calls[2].second, "raw");
  EXPECT_EQ(fake.calls[3].second, "");
  EXPECT_TRUE(warnings.empty());  // "gamma" counts as used
}

// pbrt-v3 puts (s, t) = (0, 0) at the image's lower left corner: t = 0.25 reads the bottom row.
TEST(TextureFactory, ImageTextureTIsZeroAtTheBottomRow) {
  ImageLoader topDark = [](const std::string&, const std::string&) {
    ImageBuffer img(1, 2, {"R", "G", "B"});
    for (int c = 0; c < 3; ++c) img.at(0, 0, c) = 0, img.at(0, 1, c) = 1;  // row 0 is the top
    return img;
  };
  std::vector<TextureDesc> descs = {tex("i", "float", "imagemap", {filename("rows.exr")})};
  TextureFactory f(descs, topDark);
  const Texture<Float>* t = f.scalar(test::paramSet({test::texture("x", "i")}), "x", 0, kMatLoc);
  EXPECT_NEAR(t->evaluate(atUV(0.5f, 0.25f)), 1.f, 1e-6f);
  EXPECT_NEAR(t->evaluate(atUV(0.5f, 0.75f)), 0.f, 1e-6f);
  // pbrt-v2 and the lrt draft: t = 0 at the top row.
  TextureFactory v2(descs, topDark, {}, TextureFactory::ImageOrigin::TopLeft);
  t = v2.scalar(test::paramSet({test::texture("x", "i")}), "x", 0, kMatLoc);
  EXPECT_NEAR(t->evaluate(atUV(0.5f, 0.25f)), 0.f, 1e-6f);
  EXPECT_NEAR(t->evaluate(atUV(0.5f, 0.75f)), 1.f, 1e-6f);
}

// The scene's dialect decides: a pbrt-v2 scene (SurfaceIntegrator) reads the top row at t = 0.25,
// the same scene written for pbrt-v3 (Integrator) the bottom row.
TEST(TextureFactory, ImageOriginFollowsTheSceneDialect) {
  auto centre = [](const std::string& integrator) {
    const std::string scene =
        "Film \"image\" \"integer xresolution\" [1] \"integer yresolution\" [1]\n"
        "Camera \"orthographic\" \"float screenwindow\" [-0.01 0.01 -0.01 0.01]\n"
        // The same sampler in both dialects: the same light samples, so only Kd differs.
        "Sampler \"stratified\"\n" +
        integrator +
        "\nWorldBegin\n"
        "LightSource \"infinite\" \"rgb L\" [1 1 1]\n"
        "Texture \"i\" \"spectrum\" \"imagemap\" \"string filename\" \"rows.exr\"\n"
        "Material \"matte\" \"texture Kd\" \"i\"\n"
        // A quad facing the camera with (u, v) = (0.5, 0.25) at its centre.
        "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3]\n"
        "  \"point P\" [-1 -1 5  1 -1 5  1 1 5  -1 1 5]\n"
        "  \"float uv\" [0 -0.25  1 -0.25  1 0.75  0 0.75]\n"
        "WorldEnd\n";
    test::TestRenderOptions o;
    o.build.loadImage = [](const std::string&, const std::string&) {
      ImageBuffer img(1, 2, {"R", "G", "B"});
      for (int c = 0; c < 3; ++c) img.at(0, 0, c) = 0.2f, img.at(0, 1, c) = 0.8f;  // row 0: top
      return img;
    };
    o.build.sppOverride = 4;
    return test::renderSceneText(scene, o).film().pixelValue(Point2i(0, 0)).y();
  };
  const Float v2 = centre("SurfaceIntegrator \"directlighting\"");
  const Float v3 = centre("Integrator \"directlighting\"");
  // 4 if the lookup were a point sample; the texture filter blends in a little of the other row.
  EXPECT_GT(v3 / v2, 3.5) << v2 << " " << v3;
}
