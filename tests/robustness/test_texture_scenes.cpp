// Textures in whole scenes: an image texture nobody uses is never read (so a missing file does
// not matter), a used missing one is an error naming the path and the statement, and every
// texture class survives grazing footprints (a ground plane out to the horizon, where the
// ray differentials become huge) without NaN or infinite pixels; each shape uses the texture
// definition in effect at its statement.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "core/error.h"
#include "support/render_scene.h"

namespace candela {
namespace {

const char* kHeader =
    "LookAt 0 0.05 0  0 0.05 1  0 1 0\n"
    "Camera \"perspective\" \"float fov\" [60]\n"
    "Film \"image\" \"integer xresolution\" [24] \"integer yresolution\" [16]\n"
    "Sampler \"stratified\" \"integer xsamples\" [1] \"integer ysamples\" [1]\n"
    "SurfaceIntegrator \"directlighting\"\n"
    "WorldBegin\n"
    "LightSource \"distant\" \"point from\" [0 1 -1] \"point to\" [0 0 0] \"rgb L\" [3 3 3]\n";

// A ground plane y = 0 from the camera to z = 1e5, with uv spanning 1e4 tiles.
const char* kGround =
    "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3]\n"
    "  \"point P\" [-1e5 0 0  1e5 0 0  1e5 0 1e5  -1e5 0 1e5]\n"
    "  \"float uv\" [0 0 1e4 0 1e4 1e4 0 1e4]\n";

BuildOptions withFakeImages(int* loads) {
  BuildOptions build;
  build.loadImage = [loads](const std::string& path, const std::string&) {
    if (path.find("missing") != std::string::npos)
      throw FileError(path, "cannot read texture image: no such file");
    ++*loads;
    ImageBuffer img(5, 3, {"R", "G", "B"});  // not a power of two: resampled
    for (size_t i = 0; i < img.data.size(); ++i) img.data[i] = float(i % 7) / 6;
    return img;
  };
  return build;
}

TEST(TextureScenes, UnusedImageTextureIsNeverRead) {
  int loads = 0;
  test::TestRenderOptions options;
  options.build = withFakeImages(&loads);
  std::string scene = std::string(kHeader) +
                      "Texture \"unused\" \"spectrum\" \"imagemap\" \"string filename\" "
                      "\"missing.png\"\n"
                      "Material \"matte\" \"rgb Kd\" [.5 .5 .5]\n" +
                      kGround + "WorldEnd\n";
  auto r = test::renderSceneText(scene, options);
  EXPECT_EQ(loads, 0);
  EXPECT_EQ(r.job().stats.textures, 0);
  // Even with no image reader at all.
  EXPECT_NO_THROW(test::buildSceneText(scene));
}

TEST(TextureScenes, UsedMissingImageIsAnErrorNamingThePath) {
  int loads = 0;
  std::string scene = std::string(kHeader) +
                      "Texture \"gone\" \"spectrum\" \"imagemap\" \"string filename\" "
                      "\"missing.png\"\n"
                      "Material \"matte\" \"texture Kd\" \"gone\"\n" +
                      kGround + "WorldEnd\n";
  try {
    test::buildSceneText(scene, withFakeImages(&loads));
    FAIL() << "no error";
  } catch (const SceneError& e) {
    std::string m = e.what();
    EXPECT_NE(m.find("missing.png"), std::string::npos) << m;
    EXPECT_NE(m.find("test.pbrt:8:"), std::string::npos) << m;
  }
}

TEST(TextureScenes, EveryTextureSurvivesGrazingFootprints) {
  const std::vector<std::string> textures = {
      "\"spectrum\" \"imagemap\" \"string filename\" \"a.png\"",
      "\"spectrum\" \"imagemap\" \"string filename\" \"a.png\" \"bool trilinear\" \"true\" "
      "\"string wrap\" \"black\"",
      "\"spectrum\" \"imagemap\" \"string filename\" \"a.png\" \"string wrap\" \"clamp\" "
      "\"float maxanisotropy\" [64]",
      "\"spectrum\" \"checkerboard\"",
      "\"spectrum\" \"checkerboard\" \"string aamode\" \"supersample\"",
      "\"spectrum\" \"checkerboard\" \"integer dimension\" [3]",
      "\"spectrum\" \"dots\"",
      "\"spectrum\" \"fbm\"",
      "\"spectrum\" \"wrinkled\"",
      "\"spectrum\" \"windy\"",
      "\"spectrum\" \"marble\"",
      "\"spectrum\" \"uv\"",
      "\"spectrum\" \"bilerp\"",
      "\"spectrum\" \"checkerboard\" \"string mapping\" \"spherical\"",
      "\"spectrum\" \"checkerboard\" \"string mapping\" \"cylindrical\"",
      "\"spectrum\" \"checkerboard\" \"string mapping\" \"planar\"",
  };
  for (const std::string& t : textures) {
    int loads = 0;
    test::TestRenderOptions options;
    options.build = withFakeImages(&loads);
    std::string scene = std::string(kHeader) + "Texture \"t\" " + t +
                        "\nMaterial \"matte\" \"texture Kd\" \"t\"\n" + kGround + "WorldEnd\n";
    auto r = test::renderSceneText(scene, options);
    EXPECT_EQ(r.results.front().nonFiniteSamples, 0u) << t;
    const Film& film = r.film();
    int lit = 0;
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 24; ++x) {
        Spectrum v = film.pixelValue(Point2i(x, y));
        ASSERT_TRUE(v.isFinite()) << t;
        lit += v.maxComponent() > 0;
      }
    EXPECT_GT(lit, 0) << t;
  }
}

// pbrt-v3: named textures are graphics state. Three quads each define "m" (red, green, blue) in
// their own AttributeBegin/End; each must show its own colour, not the last definition.
TEST(TextureScenes, EachShapeUsesTheTextureDefinedInItsBlock) {
  std::string scene =
      "LookAt 0 0 5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" [40]\n"
      "Film \"image\" \"integer xresolution\" [30] \"integer yresolution\" [10]\n"
      "Sampler \"stratified\" \"integer xsamples\" [1] \"integer ysamples\" [1]\n"
      "SurfaceIntegrator \"directlighting\"\nWorldBegin\n"
      "LightSource \"distant\" \"point from\" [0 0 5] \"point to\" [0 0 0] \"rgb L\" [3 3 3]\n";
  const char* colours[] = {"1 0 0", "0 1 0", "0 0 1"};
  const char* offsets[] = {"-1.2", "0", "1.2"};
  for (int i = 0; i < 3; ++i)
    scene += std::string("AttributeBegin\nTexture \"m\" \"color\" \"constant\" \"rgb value\" [") +
             colours[i] + "]\nTranslate " + offsets[i] +
             " 0 0\nMaterial \"matte\" \"texture Kd\" \"m\"\n"
             "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point P\" "
             "[-.5 -.5 0  .5 -.5 0  .5 .5 0  -.5 .5 0]\nAttributeEnd\n";
  scene += "WorldEnd\n";
  auto r = test::renderSceneText(scene);
  // The quads' centres fall on pixel columns 11, 15 and 18 of row 5.
  std::vector<int> dominant;
  for (int x : {11, 15, 18}) {
    Spectrum v = r.film().pixelValue(Point2i(x, 5));
    int c = v[0] > v[1] && v[0] > v[2] ? 0 : v[1] > v[2] ? 1 : 2;
    EXPECT_GT(v[c], 0.1f) << x;
    EXPECT_EQ(v[(c + 1) % 3] + v[(c + 2) % 3], 0.f) << x;
    dominant.push_back(c);
  }
  std::sort(dominant.begin(), dominant.end());
  EXPECT_EQ(dominant, (std::vector<int>{0, 1, 2}));
}

}  // namespace
}  // namespace candela
