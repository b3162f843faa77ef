// Image output and colour management: EXR round trips (float and half, AOV channels read back by
// name, chromaticities, metadata, compression), atomic failure, OCIO conversions against values
// computed independently, and previews.
#include "film/output/image_output.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "core/error.h"
#include "support/temp_dir.h"

namespace candela {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kAovChannels = {
    "R", "G", "B", "A", "albedo.R", "albedo.G", "albedo.B", "N.X", "N.Y", "N.Z", "Z"};

// Distinct, smooth values per pixel and channel (smooth so that lossy codecs stay close).
ImageBuffer testImage(int w, int h, const std::vector<std::string>& channels) {
  ImageBuffer img(w, h, channels);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < img.channelCount(); ++c)
        img.at(x, y, c) = 0.05f + 0.9f * float(x + 2 * y + 3 * c) / float(w + 2 * h + 3 * 11);
  return img;
}

// Compares every channel of `expected` with the channel of the same name in `actual`.
void expectSameByName(const ImageBuffer& expected, const ImageBuffer& actual, float tolerance) {
  ASSERT_EQ(actual.width, expected.width);
  ASSERT_EQ(actual.height, expected.height);
  ASSERT_EQ(actual.channelCount(), expected.channelCount());
  for (int c = 0; c < expected.channelCount(); ++c) {
    int a = actual.channelIndex(expected.channels[size_t(c)]);
    ASSERT_GE(a, 0) << "channel " << expected.channels[size_t(c)] << " missing";
    for (int y = 0; y < expected.height; ++y)
      for (int x = 0; x < expected.width; ++x) {
        float e = expected.at(x, y, c), v = actual.at(x, y, a);
        if (tolerance == 0)
          ASSERT_EQ(v, e) << expected.channels[size_t(c)] << " " << x << "," << y;
        else
          ASSERT_NEAR(v, e, tolerance * std::abs(e)) << expected.channels[size_t(c)];
      }
  }
}

std::vector<float> readChromaticities(const ImageMetadata& md) {
  std::vector<float> xy;
  for (int i = 0; i < 8; ++i) {
    const float* v = md.findFloat("chromaticities[" + std::to_string(i) + "]");
    if (!v) return {};
    xy.push_back(*v);
  }
  return xy;
}

TEST(ExrOutput, FloatRoundTripReadsAovChannelsByName) {
  TempDir dir("io");
  ImageBuffer img = testImage(13, 7, kAovChannels);
  writeExr(dir.path("aov.exr"), img, {});
  ImageBuffer back = readImage(dir.path("aov.exr"));
  expectSameByName(img, back, 0.f);
  EXPECT_EQ(back.alphaChannel(), back.channelIndex("A"));
  EXPECT_EQ(dir.entries(), std::set<std::string>{"aov.exr"});
}

TEST(ExrOutput, HalfRoundTrip) {
  TempDir dir("io");
  std::vector<std::string> channels = kAovChannels;
  for (const char* c : {"P.X", "P.Y", "P.Z", "samples"}) channels.push_back(c);
  ImageBuffer img = testImage(9, 5, channels);
  // Values half cannot hold exactly: a far position, a count above 2048.
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      img.at(x, y, img.channelIndex("P.X")) = 12345.678f + float(x);
      img.at(x, y, img.channelIndex("samples")) = float(2049 + 2 * (x + 9 * y));
    }
  writeExr(dir.path("half.exr"), img, {}, ExrOptions{.half = true});
  ImageBuffer back = readImage(dir.path("half.exr"));
  expectSameByName(img, back, 1e-3f);  // half has an 11-bit significand
  // Half really was written: a float value not representable in half comes back rounded.
  bool anyRounded = false;
  const int r = back.channelIndex("R");
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) anyRounded |= back.at(x, y, r) != img.at(x, y, 0);
  EXPECT_TRUE(anyRounded);
  // Depth, positions and sample counts stay 32-bit float.
  for (const char* name : {"Z", "P.X", "P.Y", "P.Z", "samples"})
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x)
        EXPECT_EQ(back.at(x, y, back.channelIndex(name)), img.at(x, y, img.channelIndex(name)))
            << name;
}

TEST(ExrOutput, ChromaticitiesOfLinearRec709) {
  TempDir dir("io");
  writeExr(dir.path("c.exr"), testImage(4, 4, {"R", "G", "B", "A"}), {});
  ImageMetadata md;
  readImage(dir.path("c.exr"), &md);
  std::vector<float> xy = readChromaticities(md);
  const float rec709[8] = {0.64f, 0.33f, 0.30f, 0.60f, 0.15f, 0.06f, 0.3127f, 0.3290f};
  ASSERT_EQ(xy.size(), 8u);
  for (int i = 0; i < 8; ++i) EXPECT_FLOAT_EQ(xy[size_t(i)], rec709[i]) << i;
}

TEST(ExrOutput, ChromaticitiesOfAcescg) {
  TempDir dir("io");
  writeExr(dir.path("c.exr"), testImage(4, 4, {"R", "G", "B"}), {},
           ExrOptions{.colorSpace = "acescg"});
  ImageMetadata md;
  readImage(dir.path("c.exr"), &md);
  std::vector<float> xy = readChromaticities(md);
  const float ap1[8] = {0.713f, 0.293f, 0.165f, 0.830f, 0.128f, 0.044f, 0.32168f, 0.33767f};
  ASSERT_EQ(xy.size(), 8u);
  for (int i = 0; i < 8; ++i) EXPECT_FLOAT_EQ(xy[size_t(i)], ap1[i]) << i;
  ASSERT_NE(md.findString("candela:colorSpace"), nullptr);
  EXPECT_EQ(*md.findString("candela:colorSpace"), "acescg");
}

TEST(ExrOutput, UnknownColorSpaceHasNoChromaticities) {
  TempDir dir("io");
  writeExr(dir.path("c.exr"), testImage(2, 2, {"R", "G", "B"}), {},
           ExrOptions{.colorSpace = "my_space"});
  ImageMetadata md;
  readImage(dir.path("c.exr"), &md);
  EXPECT_TRUE(readChromaticities(md).empty());
}

TEST(ExrOutput, ExplicitChromaticitiesOverrideTheLookup) {
  TempDir dir("io");
  const Chromaticities custom{{0.7f, 0.3f, 0.2f, 0.7f, 0.1f, 0.05f, 0.31f, 0.32f}};
  writeExr(dir.path("c.exr"), testImage(2, 2, {"R", "G", "B"}), {},
           ExrOptions{.colorSpace = "my_space", .chromaticities = custom});
  ImageMetadata md;
  readImage(dir.path("c.exr"), &md);
  std::vector<float> xy = readChromaticities(md);
  ASSERT_EQ(xy.size(), 8u);
  for (int i = 0; i < 8; ++i) EXPECT_FLOAT_EQ(xy[size_t(i)], custom.xy[size_t(i)]) << i;
}

TEST(ExrOutput, MetadataBecomesHeaderAttributes) {
  TempDir dir("io");
  ImageMetadata md;
  md.strings = {{"Software", "candela 0.1.0"}, {"candela:scene", "scenes/cornell.pbrt"}};
  md.ints = {{"candela:spp", 64}, {"candela:seed", 7}};
  md.floats = {{"candela:renderSeconds", 12.5f}};
  writeExr(dir.path("m.exr"), testImage(3, 2, {"R", "G", "B", "A"}), md);
  ImageMetadata back;
  readImage(dir.path("m.exr"), &back);
  ASSERT_NE(back.findString("Software"), nullptr);
  EXPECT_EQ(*back.findString("Software"), "candela 0.1.0");
  ASSERT_NE(back.findString("candela:scene"), nullptr);
  EXPECT_EQ(*back.findString("candela:scene"), "scenes/cornell.pbrt");
  ASSERT_NE(back.findInt("candela:spp"), nullptr);
  EXPECT_EQ(*back.findInt("candela:spp"), 64);
  ASSERT_NE(back.findInt("candela:seed"), nullptr);
  EXPECT_EQ(*back.findInt("candela:seed"), 7);
  ASSERT_NE(back.findFloat("candela:renderSeconds"), nullptr);
  EXPECT_EQ(*back.findFloat("candela:renderSeconds"), 12.5f);
}

TEST(ExrOutput, CompressionVariants) {
  TempDir dir("io");
  ImageBuffer img = testImage(64, 40, kAovChannels);
  for (const char* comp : {"zip", "zips", "piz", "rle", "none", "dwaa", "dwab", "dwaa:60"}) {
    SCOPED_TRACE(comp);
    std::string path = dir.path(std::string("c-") + comp + ".exr");
    writeExr(path, img, {}, ExrOptions{.compression = comp});
    ImageMetadata md;
    ImageBuffer back = readImage(path, &md);
    ASSERT_NE(md.findString("compression"), nullptr);
    const std::string base = std::string(comp).substr(0, 4);
    EXPECT_EQ(md.findString("compression")->substr(0, 4), base);
    // DWA is lossy (on float data it quantises colour channels); the rest are exact.
    expectSameByName(img, back, base == "dwaa" || base == "dwab" ? 0.05f : 0.f);
  }
}

TEST(ExrOutput, CropWindowRoundTrips) {
  TempDir dir("io");
  ImageBuffer img = testImage(5, 3, {"R", "G", "B", "A"});
  img.xOffset = 10;
  img.yOffset = 20;
  img.fullWidth = 64;
  img.fullHeight = 48;
  writeExr(dir.path("crop.exr"), img, {});
  ImageBuffer back = readImage(dir.path("crop.exr"));
  EXPECT_EQ(back.xOffset, 10);
  EXPECT_EQ(back.yOffset, 20);
  EXPECT_EQ(back.fullWidth, 64);
  EXPECT_EQ(back.fullHeight, 48);
  expectSameByName(img, back, 0.f);
}

// Expects FileError naming path and that nothing (not even a temporary file) was left behind.
template <typename F>
void expectAtomicFailure(const TempDir& dir, const std::string& path, F write,
                         const std::set<std::string>& before) {
  try {
    write();
    ADD_FAILURE() << "no FileError writing " << path;
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(path) && fs::is_regular_file(path));
  EXPECT_EQ(dir.entries(), before);
}

TEST(ExrOutput, MissingDirectoryFailsAtomically) {
  TempDir dir("io");
  std::string path = dir.path("no/such/dir/out.exr");
  expectAtomicFailure(dir, path, [&] { writeExr(path, testImage(2, 2, {"R", "G", "B"}), {}); }, {});
}

TEST(ExrOutput, UnknownCompressionFailsAtomically) {
  TempDir dir("io");
  std::string path = dir.path("out.exr");
  for (const char* comp : {"lzma", "zip:9", "dwaa:", ""}) {
    expectAtomicFailure(
        dir, path,
        [&] {
          writeExr(path, testImage(2, 2, {"R", "G", "B"}), {}, {.compression = comp});
        },
        {});
  }
}

TEST(ExrOutput, FailedRenameLeavesNoTemporaryFile) {
  // The target is a non-empty directory: the image is written to the temporary file, the rename
  // fails, and the temporary file must be removed again.
  TempDir dir("io");
  std::string path = dir.path("taken.exr");
  fs::create_directories(fs::path(path) / "inside");
  expectAtomicFailure(dir, path,
                      [&] {
                        writeExr(path, testImage(2, 2, {"R", "G", "B"}), {});
                      },
                      {"taken.exr"});
  EXPECT_TRUE(fs::is_directory(fs::path(path) / "inside"));
}

TEST(ExrOutput, UnwritableDirectoryFailsAtomically) {
  TempDir dir("io");
  fs::create_directories(dir.path("ro"));
  std::string path = dir.path("ro/out.exr");
  if (::geteuid() == 0) {
    // Root ignores permission bits; a parent that is a regular file fails for anyone.
    std::ofstream(dir.path("plainfile")) << "x";
    path = dir.path("plainfile/out.exr");
  } else {
    fs::permissions(dir.path("ro"), fs::perms::owner_read | fs::perms::owner_exec);
  }
  try {
    writeExr(path, testImage(2, 2, {"R", "G", "B"}), {});
    ADD_FAILURE() << "no FileError";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  fs::permissions(dir.path("ro"), fs::perms::owner_all);
  EXPECT_TRUE(fs::is_empty(dir.path("ro")));
  EXPECT_FALSE(fs::exists(path));
}

TEST(ExrOutput, InconsistentBufferFails) {
  TempDir dir("io");
  ImageBuffer img = testImage(4, 4, {"R", "G", "B"});
  img.data.pop_back();
  std::string path = dir.path("bad.exr");
  expectAtomicFailure(dir, path, [&] { writeExr(path, img, {}); }, {});
  ImageBuffer dup = testImage(2, 2, {"R", "G", "R"});
  expectAtomicFailure(dir, path, [&] { writeExr(path, dup, {}); }, {});
}

TEST(ExrOutput, OverwriteReplacesExistingFile) {
  TempDir dir("io");
  std::string path = dir.path("o.exr");
  writeExr(path, testImage(2, 2, {"R", "G", "B"}), {});
  writeExr(path, testImage(6, 3, {"R", "G", "B", "A"}), {});
  EXPECT_EQ(readImage(path).width, 6);
  EXPECT_EQ(dir.entries(), std::set<std::string>{"o.exr"});
}

TEST(ImageRead, MissingOrCorruptFileThrows) {
  TempDir dir("io");
  EXPECT_THROW(readImage(dir.path("missing.exr")), FileError);
  std::ofstream(dir.path("garbage.exr"), std::ios::binary) << "this is not an OpenEXR file";
  EXPECT_THROW(readImage(dir.path("garbage.exr")), FileError);
  // A real EXR cut in half: the header reads, the pixels do not.
  writeExr(dir.path("full.exr"), testImage(64, 64, kAovChannels), {},
           ExrOptions{.compression = "none"});
  std::ifstream in(dir.path("full.exr"), std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream(dir.path("cut.exr"), std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  EXPECT_THROW(readImage(dir.path("cut.exr")), FileError);
}

// --- OpenColorIO ------------------------------------------------------------------------------

ImageBuffer onePixel(float r, float g, float b, float a = 0.25f) {
  ImageBuffer img(1, 1, {"R", "G", "B", "A"});
  img.data = {r, g, b, a};
  return img;
}

TEST(OcioColor, DefaultConfigLoads) {
  ColorManagement cm;
  EXPECT_EQ(cm.configPath(), CANDELA_DEFAULT_OCIO_CONFIG);
  EXPECT_EQ(cm.sceneLinearName(), "lin_rec709");
  for (const char* name : {"lin_rec709", "Linear", "linear", "Linear Rec.709 (sRGB)", "acescg",
                           "srgb_texture", "raw", "srgb_display", "scene_linear"})
    EXPECT_TRUE(cm.hasColorSpace(name)) << name;
  EXPECT_FALSE(cm.hasColorSpace("no_such_space"));
  EXPECT_EQ(cm.canonicalName("Linear"), "lin_rec709");
  EXPECT_EQ(cm.displays(), std::vector<std::string>{"sRGB"});
  EXPECT_EQ(cm.views("sRGB"), (std::vector<std::string>{"Standard", "Raw"}));
}

TEST(OcioColor, MissingOrInvalidConfigThrowsFileError) {
  TempDir dir("io");
  try {
    ColorManagement cm(dir.path("nope.ocio"));
    ADD_FAILURE() << "no FileError";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("nope.ocio"), std::string::npos);
  }
  std::ofstream(dir.path("bad.ocio")) << "ocio_profile_version: 2\nroles: [this is: not valid\n";
  try {
    ColorManagement cm(dir.path("bad.ocio"));
    ADD_FAILURE() << "no FileError";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.ocio"), std::string::npos);
  }
}

TEST(OcioColor, EnvironmentVariableSelectsConfig) {
  const char* old = std::getenv("OCIO");
  std::string saved = old ? old : "";
  ::setenv("OCIO", "/nonexistent/candela/env.ocio", 1);
  EXPECT_THROW(ColorManagement cm, FileError);
  ::setenv("OCIO", CANDELA_DEFAULT_OCIO_CONFIG, 1);
  EXPECT_NO_THROW(ColorManagement cm);
  if (old)
    ::setenv("OCIO", saved.c_str(), 1);
  else
    ::unsetenv("OCIO");
}

TEST(OcioColor, SrgbDisplayOfMiddleGreyAndWhite) {
  ColorManagement cm;
  ImageBuffer img(2, 1, {"R", "G", "B", "A"});
  img.data = {0.18f, 0.18f, 0.18f, 0.5f, 1.f, 1.f, 1.f, 0.75f};
  cm.toDisplay(img, "sRGB", "Standard");
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(img.at(0, 0, c), 0.4614f, 1e-3f);
    EXPECT_NEAR(img.at(1, 0, c), 1.f, 1e-5f);
  }
  EXPECT_EQ(img.at(0, 0, 3), 0.5f);  // alpha untouched
  EXPECT_EQ(img.at(1, 0, 3), 0.75f);
  ImageBuffer raw = onePixel(0.18f, 0.5f, 2.f);
  cm.toDisplay(raw, "sRGB", "Raw");
  EXPECT_EQ(raw.data, onePixel(0.18f, 0.5f, 2.f).data);
  EXPECT_THROW(cm.toDisplay(raw, "sRGB", "Filmic"), SceneError);
}

TEST(OcioColor, LinearRedToAcescgAndBack) {
  ColorManagement cm;
  ImageBuffer img = onePixel(1.f, 0.f, 0.f);
  cm.convert(img, "lin_rec709", "acescg");
  EXPECT_NEAR(img.data[0], 0.6131f, 1e-4f);
  EXPECT_NEAR(img.data[1], 0.0702f, 1e-4f);
  EXPECT_NEAR(img.data[2], 0.0206f, 1e-4f);
  EXPECT_EQ(img.data[3], 0.25f);
  cm.convert(img, "ACEScg", "Linear");  // by alias
  EXPECT_NEAR(img.data[0], 1.f, 1e-5f);
  EXPECT_NEAR(img.data[1], 0.f, 1e-5f);
  EXPECT_NEAR(img.data[2], 0.f, 1e-5f);
}

TEST(OcioColor, ConvertLeavesExtraChannelsAlone) {
  ColorManagement cm;
  ImageBuffer img = testImage(3, 2, kAovChannels);
  ImageBuffer before = img;
  cm.convert(img, "srgb_texture", "scene_linear");
  for (size_t i = 0; i < img.pixelCount(); ++i)
    for (size_t c = 3; c < kAovChannels.size(); ++c)
      EXPECT_EQ(img.data[i * kAovChannels.size() + c], before.data[i * kAovChannels.size() + c]);
  // sRGB-encoded 0.5 is linear 0.2140.
  ImageBuffer half = onePixel(0.5f, 0.5f, 0.5f);
  cm.convert(half, "srgb_texture", "lin_rec709");
  EXPECT_NEAR(half.data[0], 0.2140f, 1e-4f);
}

TEST(OcioColor, UnknownNamesAndBadImagesThrow) {
  ColorManagement cm;
  ImageBuffer img = onePixel(1, 1, 1);
  EXPECT_THROW(cm.convert(img, "lin_rec709", "no_such_space"), SceneError);
  ImageBuffer grey(1, 1, {"Y"});
  EXPECT_THROW(cm.convert(grey, "lin_rec709", "acescg"), std::invalid_argument);
}

TEST(OcioColor, ChromaticitiesLookup) {
  ColorManagement cm;
  auto rec709 = cm.chromaticities("Linear");
  ASSERT_TRUE(rec709.has_value());
  EXPECT_FLOAT_EQ(rec709->xy[0], 0.64f);
  EXPECT_FLOAT_EQ(rec709->xy[7], 0.3290f);
  auto role = cm.chromaticities("scene_linear");
  ASSERT_TRUE(role.has_value());
  EXPECT_FLOAT_EQ(role->xy[0], 0.64f);
  auto cg = cm.chromaticities("acescg");
  ASSERT_TRUE(cg.has_value());
  EXPECT_FLOAT_EQ(cg->xy[2], 0.165f);
  EXPECT_FLOAT_EQ(cg->xy[6], 0.32168f);
  EXPECT_FALSE(cm.chromaticities("raw").has_value());
  EXPECT_FALSE(cm.chromaticities("no_such_space").has_value());
  EXPECT_FALSE(knownChromaticities("something_else").has_value());
}

// --- previews ---------------------------------------------------------------------------------

TEST(PreviewOutput, PngThroughSrgbView) {
  TempDir dir("io");
  ColorManagement cm;
  ImageBuffer img(3, 2, {"R", "G", "B", "A"});
  const float values[6] = {0.f, 0.18f, 1.f, 4.f, -1.f, 0.5f};
  for (int i = 0; i < 6; ++i)
    for (int c = 0; c < 4; ++c) img.at(i % 3, i / 3, c) = c == 3 ? 0.5f : values[i];
  writePreview(dir.path("p.png"), img, cm);
  EXPECT_EQ(dir.entries(), std::set<std::string>{"p.png"});
  ImageBuffer back = readImage(dir.path("p.png"));
  ASSERT_EQ(back.width, 3);
  ASSERT_EQ(back.height, 2);
  ASSERT_EQ(back.channelCount(), 3);
  const float expected[6] = {0.f, 0.4614f, 1.f, 1.f, 0.f, 0.7354f};  // clamped after the view
  for (int i = 0; i < 6; ++i)
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(back.at(i % 3, i / 3, c), expected[i], 0.6f / 255.f) << i;
}

TEST(PreviewOutput, JpegAndErrors) {
  TempDir dir("io");
  ColorManagement cm;
  ImageBuffer img = testImage(16, 8, {"R", "G", "B"});
  writePreview(dir.path("p.jpg"), img, cm);
  ImageBuffer back = readImage(dir.path("p.jpg"));
  EXPECT_EQ(back.width, 16);
  EXPECT_EQ(back.channelCount(), 3);
  std::string tif = dir.path("p.tif");
  expectAtomicFailure(dir, tif, [&] { writePreview(tif, img, cm); }, {"p.jpg"});
  std::string missing = dir.path("none/p.png");
  expectAtomicFailure(dir, missing, [&] { writePreview(missing, img, cm); }, {"p.jpg"});
}

}  // namespace
}  // namespace candela
