// Image texture files (OpenEXR through OpenEXR, PNG through the OpenImageIO plug-in, chosen by
// the file's contents) and OpenColorIO: the default colour-space rule (8-bit files are
// sRGB-encoded, float files linear), overrides by name or alias, errors naming the path, and an
// image texture made by the TextureFactory with this loader; light maps, which pbrt-v2/v3 read
// undecoded, 8-bit files included.
#include "film/output/texture_loader.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "assembly/plugin_factories.h"
#include "assembly/texture_factory.h"
#include "core/error.h"
#include "lights/goniometric_light.h"
#include "lights/projection_light.h"
#include "support/param_items.h"
#include "support/temp_dir.h"

namespace candela {
namespace {

namespace fs = std::filesystem;

// The sRGB decoding (IEC 61966-2-1), written out independently of OCIO.
double srgbToLinear(double v) {
  return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

ImageBuffer flat(int w, int h, std::vector<std::string> channels, std::vector<float> value) {
  ImageBuffer img(w, h, std::move(channels));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < img.channelCount(); ++c) img.at(x, y, c) = value[size_t(c)];
  return img;
}

// An 8-bit PNG whose every sample is the code 128 (0.50196 encoded): written through the
// preview writer, whose sRGB view encodes linear srgbToLinear(128 / 255) to exactly that code.
std::string write128Png(const TempDir& dir, const ColorManagement& cm) {
  std::string path = dir.path("grey128.png");
  float linear = float(srgbToLinear(128.0 / 255.0));
  writePreview(path, flat(4, 3, {"R", "G", "B"}, {linear, linear, linear}), cm);
  return path;
}

void expectAll(const ImageBuffer& img, float r, float g, float b, float tolerance) {
  ASSERT_EQ(img.channels, (std::vector<std::string>{"R", "G", "B"}));
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      EXPECT_NEAR(img.at(x, y, 0), r, tolerance);
      EXPECT_NEAR(img.at(x, y, 1), g, tolerance);
      EXPECT_NEAR(img.at(x, y, 2), b, tolerance);
    }
}

TEST(TextureLoader, DefaultRuleByPixelType) {
  ColorManagement cm;
  EXPECT_EQ(defaultTextureColorSpace(true, cm), "srgb_texture");
  EXPECT_EQ(defaultTextureColorSpace(false, cm), cm.sceneLinearName());
}

TEST(TextureLoader, EightBitFilesAreSrgbEncoded) {
  TempDir dir("tex");
  ColorManagement cm;
  std::string png = write128Png(dir, cm);
  ImageBuffer img = loadTextureImage(png, "", cm);
  EXPECT_EQ(img.width, 4);
  EXPECT_EQ(img.height, 3);
  float expected = float(srgbToLinear(128.0 / 255.0));  // 0.2158
  expectAll(img, expected, expected, expected, 2e-4f);
  EXPECT_NEAR(img.at(0, 0, 0), 0.214f, 0.003f);  // "0.5" in sRGB is about 0.214 linear
  // Overrides: data is not converted; the linear space by an alias is not converted either.
  expectAll(loadTextureImage(png, "raw", cm), 128.f / 255, 128.f / 255, 128.f / 255, 1e-6f);
  expectAll(loadTextureImage(png, "linear", cm), 128.f / 255, 128.f / 255, 128.f / 255, 1e-6f);
  expectAll(loadTextureImage(png, "sRGB - Texture", cm), expected, expected, expected, 2e-4f);
}

TEST(TextureLoader, SixteenBitAndGreyIntegerFilesAreSrgbEncoded) {
  // Made with oiiotool: 2x2 RGB uint16 of 0.5 (code 32768) and 3x2 one-channel uint8 of 128.
  ColorManagement cm;
  const std::string dir = std::string(CANDELA_TEST_DATA_DIR) + "/textures/";
  float v16 = float(srgbToLinear(32768.0 / 65535.0));
  expectAll(loadTextureImage(dir + "grey16.png", "", cm), v16, v16, v16, 2e-4f);
  float v8 = float(srgbToLinear(128.0 / 255.0));
  ImageBuffer grey = loadTextureImage(dir + "grey8.png", "", cm);
  EXPECT_EQ(grey.width, 3);
  expectAll(grey, v8, v8, v8, 2e-4f);
}

TEST(TextureLoader, FloatFilesAreLinear) {
  TempDir dir("tex");
  ColorManagement cm;
  std::string exr = dir.path("colour.exr");
  // Channels are looked up by name (EXR stores them sorted); alpha is dropped.
  writeExr(exr, flat(3, 2, {"R", "G", "B", "A"}, {0.5f, 0.2f, 0.1f, 0.25f}), ImageMetadata{});
  expectAll(loadTextureImage(exr, "", cm), 0.5f, 0.2f, 0.1f, 0);
  std::string half = dir.path("half.exr");
  ExrOptions options;
  options.half = true;
  writeExr(half, flat(2, 2, {"R", "G", "B"}, {0.5f, 0.5f, 0.5f}), ImageMetadata{}, options);
  expectAll(loadTextureImage(half, "", cm), 0.5f, 0.5f, 0.5f, 0);
  // Declared sRGB-encoded, an EXR's 0.5 is decoded.
  float decoded = float(srgbToLinear(0.5));
  expectAll(loadTextureImage(half, "srgb_texture", cm), decoded, decoded, decoded, 2e-4f);
}

TEST(TextureLoader, TheFormatIsTheFilesNotTheNames) {
  // Read by their contents: a PNG named .exr is still 8-bit sRGB, an EXR named .png still float.
  TempDir dir("tex");
  ColorManagement cm;
  const std::string png = std::string(CANDELA_TEST_DATA_DIR) + "/textures/grey8.png";
  const std::string pngAsExr = dir.path("png.exr");
  std::filesystem::copy_file(png, pngAsExr);
  float v8 = float(srgbToLinear(128.0 / 255.0));
  expectAll(loadTextureImage(pngAsExr, "", cm), v8, v8, v8, 2e-4f);
  const std::string exrAsPng = dir.path("exr.png");
  writeExr(exrAsPng, flat(2, 2, {"R", "G", "B"}, {0.5f, 0.25f, 0.125f}), ImageMetadata{});
  expectAll(loadTextureImage(exrAsPng, "", cm), 0.5f, 0.25f, 0.125f, 0);
}

TEST(TextureLoader, GreyImagesBecomeGreyRgb) {
  TempDir dir("tex");
  ColorManagement cm;
  std::string exr = dir.path("grey.exr");
  writeExr(exr, flat(2, 2, {"Y"}, {0.75f}), ImageMetadata{});
  expectAll(loadTextureImage(exr, "", cm), 0.75f, 0.75f, 0.75f, 0);
}

TEST(TextureLoader, ErrorsNameThePath) {
  TempDir dir("tex");
  ColorManagement cm;
  auto message = [&](const std::string& path, const std::string& colorSpace) -> std::string {
    try {
      loadTextureImage(path, colorSpace, cm);
    } catch (const std::exception& e) {
      return e.what();
    }
    return "(no error)";
  };
  std::string missing = dir.path("missing.png");
  EXPECT_NE(message(missing, "").find(missing), std::string::npos);
  std::string corrupt = dir.path("corrupt.png");
  std::ofstream(corrupt) << "this is not a PNG file";
  std::string e = message(corrupt, "");
  EXPECT_NE(e.find(corrupt), std::string::npos) << e;
  EXPECT_THROW(loadTextureImage(corrupt, "", cm), FileError);
  std::string png = write128Png(dir, cm);
  EXPECT_NE(message(png, "no_such_space").find("no_such_space"), std::string::npos);
}

TEST(TextureLoader, ImageTextureThroughTheFactory) {
  TempDir dir("tex");
  ColorManagement cm;
  write128Png(dir, cm);
  TextureDesc d;
  d.textureName = "grey";
  d.type = "spectrum";
  d.name = "imagemap";
  d.loc = FileLoc{dir.path("scene.pbrt"), 2, 1};
  // Relative to the scene file's directory.
  d.params.add(test::strings("filename", {"grey128.png"}, d.loc));
  std::vector<TextureDesc> descs = {d};
  int loads = 0;
  TextureFactory f(descs, [&](const std::string& path, const std::string& colorSpace) {
    ++loads;
    return loadTextureImage(path, colorSpace, cm);
  });
  ParamSet material = test::paramSet({test::texture("Kd", "grey")});
  const Texture<Spectrum>* t = f.spectrum(material, "Kd", Spectrum(1), FileLoc{});
  f.spectrum(material, "Kd", Spectrum(1), FileLoc{});
  EXPECT_EQ(loads, 1);
  SurfaceInteraction si;
  si.uv = Point2f(0.4f, 0.6f);
  EXPECT_NEAR(t->evaluate(si)[1], srgbToLinear(128.0 / 255.0), 2e-4);
}

TEST(LightMaps, EightBitFilesAreReadUndecodedAsPbrtDoes) {
  // pbrt-v3's goniometric and projection lights (and v2's) take an 8-bit image's codes / 255 as
  // they are: code 128 is 0.502, where an image texture decodes it to 0.216.
  TempDir dir("tex");
  ColorManagement cm;
  std::string png = write128Png(dir, cm);
  auto load = [&cm](const std::string& path, const std::string& colorSpace) {
    return loadTextureImage(path, colorSpace, cm);
  };
  for (const char* kind : {"goniometric", "projection"}) {
    LightDesc desc;
    desc.name = kind;
    desc.params.add(test::strings("mapname", {png}));
    desc.params.add(test::floats("fov", {60}));
    std::unique_ptr<Light> light = createLight(desc, load);
    Spectrum v = desc.name == "goniometric"
                     ? static_cast<const GoniometricLight&>(*light).scale(Vector3f(0, 1, 0))
                     : static_cast<const ProjectionLight&>(*light).projection(Vector3f(0, 0, 1));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(v[c], 128.0 / 255, 2e-3) << kind;
  }
}

}  // namespace
}  // namespace candela
