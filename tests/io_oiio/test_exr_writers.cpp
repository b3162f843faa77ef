// The OpenEXR files candela writes through OpenEXR directly are the files OpenImageIO's writer gave
// before (the reference writer below is what writeExr did then): the same header attributes,
// byte for byte, the same channels and types, and the same pixel bits; and both OpenEXR and
// OpenImageIO read them back as written. This folder links OpenImageIO itself, which the io tests
// no longer do (it costs every test process 0.18 s to load).
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "film/output/image_output.h"
#include "support/temp_dir.h"

namespace candela {
namespace {

namespace fs = std::filesystem;

// writeExr as it was through OpenImageIO (commit 5bb789f), the reference for the direct writer.
void writeExrThroughOiio(const std::string& path, const ImageBuffer& image,
                         const ImageMetadata& metadata, const ExrOptions& options) {
  OIIO::ImageSpec spec(image.width, image.height, image.channelCount(),
                       options.half ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT);
  spec.channelnames = image.channels;
  if (options.half) {
    spec.channelformats.assign(size_t(image.channelCount()), OIIO::TypeDesc::HALF);
    bool anyFloat = false;
    for (size_t c = 0; c < image.channels.size(); ++c) {
      const std::string& name = image.channels[c];
      if (name == "Z" || name.rfind("P.", 0) == 0 || name == "samples") {
        spec.channelformats[c] = OIIO::TypeDesc::FLOAT;
        anyFloat = true;
      }
    }
    if (!anyFloat) spec.channelformats.clear();
  }
  spec.alpha_channel = image.alphaChannel();
  spec.z_channel = image.channelIndex("Z");
  spec.x = image.xOffset;
  spec.y = image.yOffset;
  spec.full_x = 0;
  spec.full_y = 0;
  spec.full_width = image.displayWidth();
  spec.full_height = image.displayHeight();
  spec.attribute("compression", options.compression);
  spec.attribute("oiio:ColorSpace", options.colorSpace);
  spec.attribute("candela:colorSpace", options.colorSpace);
  if (auto chroma =
          options.chromaticities ? options.chromaticities : knownChromaticities(options.colorSpace))
    spec.attribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8), chroma->xy.data());
  for (const auto& [name, value] : metadata.strings) spec.attribute(name, value);
  for (const auto& [name, value] : metadata.floats) spec.attribute(name, value);
  for (const auto& [name, value] : metadata.ints) spec.attribute(name, value);
  auto out = OIIO::ImageOutput::create("openexr");
  ASSERT_TRUE(out && out->open(path, spec)) << OIIO::geterror();
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, image.data.data())) << out->geterror();
  ASSERT_TRUE(out->close());
}

// An attribute's value as OpenEXR serialises it.
class ByteStream : public Imf::OStream {
 public:
  ByteStream() : Imf::OStream("memory") {}
  void write(const char c[], int n) override { bytes.append(c, size_t(n)); }
  uint64_t tellp() override { return bytes.size(); }
  void seekp(uint64_t pos) override { bytes.resize(pos); }
  std::string bytes;
};

std::map<std::string, std::string> serialisedAttributes(const std::string& path) {
  Imf::InputFile file(path.c_str());
  std::map<std::string, std::string> result;
  for (auto it = file.header().begin(); it != file.header().end(); ++it) {
    ByteStream s;
    it.attribute().writeValueTo(s, 2);
    result[it.name()] = std::string(it.attribute().typeName()) + ":" + s.bytes;
  }
  return result;
}

// Every channel of the file as float, by name, through OpenEXR.
std::map<std::string, std::vector<float>> exrPixels(const std::string& path) {
  Imf::InputFile file(path.c_str());
  const Imath::Box2i dw = file.header().dataWindow();
  const size_t n = size_t(dw.max.x - dw.min.x + 1) * size_t(dw.max.y - dw.min.y + 1);
  std::map<std::string, std::vector<float>> result;
  Imf::FrameBuffer frame;
  for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it) {
    std::vector<float>& v = result[it.name()];
    v.resize(n);
    frame.insert(it.name(), Imf::Slice::Make(Imf::FLOAT, v.data(), dw));
  }
  file.setFrameBuffer(frame);
  file.readPixels(dw.min.y, dw.max.y);
  return result;
}

std::map<std::string, int> exrChannelTypes(const std::string& path) {
  Imf::InputFile file(path.c_str());
  std::map<std::string, int> result;
  for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it)
    result[it.name()] = int(it.channel().type);
  return result;
}

ImageBuffer testImage(int w, int h, const std::vector<std::string>& channels) {
  ImageBuffer img(w, h, channels);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < img.channelCount(); ++c)
        img.at(x, y, c) = 0.05f + 0.9f * float(x + 2 * y + 3 * c) / float(w + 2 * h + 33) +
                          (c == 0 ? 1e-4f * float((x * 7919 + y * 104729) % 97) : 0.f);
  return img;
}

struct Case {
  std::string name;
  ImageBuffer image;
  ExrOptions options;
};

std::vector<Case> cases() {
  const std::vector<std::string> aovs = {"R",        "G",        "B",   "A",   "albedo.R",
                                         "albedo.G", "albedo.B", "N.X", "N.Y", "N.Z",
                                         "Z",        "P.X",      "P.Y", "P.Z", "samples"};
  std::vector<Case> list;
  list.push_back({"float-aovs", testImage(37, 21, aovs), {}});
  list.push_back({"half-aovs", testImage(37, 21, aovs), {.half = true}});
  list.push_back({"half-rgba", testImage(16, 40, {"R", "G", "B", "A"}), {.half = true}});
  ImageBuffer crop = testImage(5, 3, {"R", "G", "B", "A"});
  crop.xOffset = 10;
  crop.yOffset = 20;
  crop.fullWidth = 64;
  crop.fullHeight = 48;
  list.push_back({"crop", crop, {}});
  for (const char* c :
       {"none", "rle", "zips", "piz", "pxr24", "b44", "b44a", "dwaa", "dwab", "dwaa:60"})
    list.push_back({std::string("compression-") + c,
                    testImage(64, 40, aovs),
                    {.half = std::string(c) == "b44", .compression = c}});
  list.push_back({"acescg", testImage(4, 4, {"R", "G", "B"}), {.colorSpace = "acescg"}});
  list.push_back({"unknown-space", testImage(4, 4, {"R", "G", "B"}), {.colorSpace = "my_space"}});
  list.push_back(
      {"explicit-chromaticities",
       testImage(4, 4, {"R", "G", "B"}),
       {.colorSpace = "my_space",
        .chromaticities = Chromaticities{{0.7f, 0.3f, 0.2f, 0.7f, 0.1f, 0.05f, 0.31f, 0.32f}}}});
  // A frame of 1080 rows: OpenEXR compresses it on several threads.
  list.push_back({"tall", testImage(8, 1080, {"R", "G", "B", "A"}), {}});
  return list;
}

ImageMetadata renderMetadata() {
  ImageMetadata md;
  md.strings = {{"Software", "candela 0.1.0"},
                {"candela:scene", "scenes/cornell.pbrt"},
                {"candela:seed", "18446744073709551615"},
                {"DateTime", "2025:01:02 03:04:05"}};
  md.ints = {{"candela:spp", 64}, {"candela:passes", 3}};
  md.floats = {{"candela:renderSeconds", 12.5f}, {"candela:relmse", 1.25e-3f}};
  return md;
}

TEST(ExrWriters, DirectWriterGivesTheFileOpenImageIOGave) {
  TempDir dir("exrw");
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const std::string direct = dir.path(c.name + "-direct.exr");
    const std::string oiio = dir.path(c.name + "-oiio.exr");
    writeExr(direct, c.image, renderMetadata(), c.options);
    writeExrThroughOiio(oiio, c.image, renderMetadata(), c.options);

    const auto attributes = serialisedAttributes(direct);
    EXPECT_EQ(attributes, serialisedAttributes(oiio));
    EXPECT_EQ(attributes.count("capDate"), 1u);  // DateTime under OpenEXR's name
    EXPECT_EQ(exrChannelTypes(direct), exrChannelTypes(oiio));

    const auto pixels = exrPixels(direct), reference = exrPixels(oiio);
    ASSERT_EQ(pixels.size(), size_t(c.image.channelCount()));
    ASSERT_EQ(reference.size(), pixels.size());
    for (const auto& [name, values] : pixels) {
      ASSERT_EQ(reference.count(name), 1u) << name;
      const std::vector<float>& ref = reference.at(name);
      ASSERT_EQ(values.size(), ref.size());
      EXPECT_EQ(std::memcmp(values.data(), ref.data(), values.size() * sizeof(float)), 0)
          << "channel " << name << " differs";
    }
  }
}

TEST(ExrWriters, LosslessFilesReadBackAsWrittenByBothLibraries) {
  TempDir dir("exrw");
  for (const Case& c : cases()) {
    if (c.options.half || c.name.find("dwa") != std::string::npos ||
        c.name.find("b44") != std::string::npos || c.name.find("pxr24") != std::string::npos)
      continue;  // lossy: compared with the reference writer above
    SCOPED_TRACE(c.name);
    const std::string path = dir.path(c.name + ".exr");
    writeExr(path, c.image, renderMetadata(), c.options);
    const auto pixels = exrPixels(path);
    auto in = OIIO::ImageInput::open(path);
    ASSERT_TRUE(in) << OIIO::geterror();
    const OIIO::ImageSpec spec = in->spec();
    ASSERT_EQ(spec.nchannels, c.image.channelCount());
    EXPECT_EQ(spec.x, c.image.xOffset);
    EXPECT_EQ(spec.full_width, c.image.displayWidth());
    std::vector<float> oiioPixels(c.image.data.size());
    ASSERT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, oiioPixels.data()));
    const ImageBuffer direct = readImage(path);
    for (int ch = 0; ch < c.image.channelCount(); ++ch) {
      const std::string& name = c.image.channels[size_t(ch)];
      const int o = spec.channelindex(name), d = direct.channelIndex(name);
      ASSERT_GE(o, 0) << name;
      ASSERT_GE(d, 0) << name;
      for (size_t i = 0; i < c.image.pixelCount(); ++i) {
        const float expected = c.image.data[i * c.image.channels.size() + size_t(ch)];
        ASSERT_EQ(pixels.at(name)[i], expected) << name;
        ASSERT_EQ(oiioPixels[i * size_t(spec.nchannels) + size_t(o)], expected) << name;
        ASSERT_EQ(direct.data[i * direct.channels.size() + size_t(d)], expected) << name;
      }
    }
  }
}

TEST(ExrWriters, DirectReaderGivesOpenImageIOsMetadata) {
  TempDir dir("exrw");
  const std::string path = dir.path("m.exr");
  writeExr(path, testImage(3, 2, {"R", "G", "B", "A"}), renderMetadata(),
           ExrOptions{.compression = "dwaa:60", .colorSpace = "acescg"});
  ImageMetadata direct;
  readImage(path, &direct);
  auto in = OIIO::ImageInput::open(path);
  ASSERT_TRUE(in);
  const OIIO::ImageSpec& spec = in->spec();
  for (const char* name : {"Software", "candela:scene", "candela:seed", "DateTime",
                           "candela:colorSpace", "compression"}) {
    ASSERT_NE(direct.findString(name), nullptr) << name;
    EXPECT_EQ(*direct.findString(name), spec.get_string_attribute(name)) << name;
  }
  for (const char* name : {"candela:spp", "candela:passes"}) {
    ASSERT_NE(direct.findInt(name), nullptr) << name;
    EXPECT_EQ(*direct.findInt(name), spec.get_int_attribute(name)) << name;
  }
  for (const char* name : {"candela:renderSeconds", "candela:relmse"}) {
    ASSERT_NE(direct.findFloat(name), nullptr) << name;
    EXPECT_EQ(*direct.findFloat(name), spec.get_float_attribute(name)) << name;
  }
  const OIIO::ParamValue* chroma = spec.find_attribute("chromaticities");
  ASSERT_NE(chroma, nullptr);
  for (int i = 0; i < 8; ++i) {
    const float* v = direct.findFloat("chromaticities[" + std::to_string(i) + "]");
    ASSERT_NE(v, nullptr) << i;
    EXPECT_EQ(*v, chroma->get_float_indexed(i)) << i;
  }
}

}  // namespace
}  // namespace candela
