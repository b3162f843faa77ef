#include "film/output/exr_file.h"

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfChromaticitiesAttribute.h>
#include <OpenEXR/ImfCompressionAttribute.h>
#include <OpenEXR/ImfDoubleAttribute.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfMatrixAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfThreading.h>
#include <OpenEXR/ImfVecAttribute.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <thread>
#include <utility>
#include <vector>

namespace candela {

namespace {

struct CodecName {
  const char* name;
  Imf::Compression compression;
};
constexpr std::array<CodecName, 10> kCodecs = {{{"none", Imf::NO_COMPRESSION},
                                                {"rle", Imf::RLE_COMPRESSION},
                                                {"zips", Imf::ZIPS_COMPRESSION},
                                                {"zip", Imf::ZIP_COMPRESSION},
                                                {"piz", Imf::PIZ_COMPRESSION},
                                                {"pxr24", Imf::PXR24_COMPRESSION},
                                                {"b44", Imf::B44_COMPRESSION},
                                                {"b44a", Imf::B44A_COMPRESSION},
                                                {"dwaa", Imf::DWAA_COMPRESSION},
                                                {"dwab", Imf::DWAB_COMPRESSION}}};

// EXR attribute names that OpenImageIO (and so candela's metadata) calls otherwise.
constexpr std::array<std::pair<const char*, const char*>, 3> kRenamed = {
    {{"DateTime", "capDate"}, {"ImageDescription", "comments"}, {"Copyright", "owner"}}};

std::string exrName(const std::string& name) {
  for (const auto& [ours, exr] : kRenamed)
    if (name == ours) return exr;
  return name;
}

std::string ourName(const std::string& name) {
  for (const auto& [ours, exr] : kRenamed)
    if (name == exr) return ours;
  return name;
}

bool keepsFloat(const std::string& channel) {
  // Depth, positions and sample counts: half's 11-bit significand and 65504 maximum are fine for
  // colour, not for distances, coordinates or counts above 2048.
  return channel == "Z" || channel.rfind("P.", 0) == 0 || channel == "samples";
}

// R, G, B, A first within a layer ("albedo" of "albedo.R"), the rest after them; layers by name.
std::pair<std::string, int> channelOrderKey(const std::string& name) {
  const size_t dot = name.rfind('.');
  const std::string layer = dot == std::string::npos ? "" : name.substr(0, dot);
  const std::string component = dot == std::string::npos ? name : name.substr(dot + 1);
  int rank = 4;
  for (int i = 0; i < 4; ++i)
    if (component == std::string(1, "RGBA"[i])) rank = i;
  return {layer, rank};
}

template <typename T>
const T* as(const Imf::Attribute& attribute) {
  return dynamic_cast<const T*>(&attribute);
}

void pushFloats(ImageMetadata* metadata, const std::string& name, const float* values, int n) {
  for (int i = 0; i < n; ++i)
    metadata->floats.emplace_back(name + "[" + std::to_string(i) + "]", values[i]);
}

void collectMetadata(const Imf::Header& header, ImageMetadata* metadata) {
  for (auto it = header.begin(); it != header.end(); ++it) {
    const std::string name = ourName(it.name());
    const Imf::Attribute& a = it.attribute();
    if (auto* s = as<Imf::StringAttribute>(a)) {
      metadata->strings.emplace_back(name, s->value());
    } else if (auto* i = as<Imf::IntAttribute>(a)) {
      metadata->ints.emplace_back(name, i->value());
    } else if (auto* f = as<Imf::FloatAttribute>(a)) {
      metadata->floats.emplace_back(name, f->value());
    } else if (auto* d = as<Imf::DoubleAttribute>(a)) {
      metadata->floats.emplace_back(name, float(d->value()));
    } else if (auto* c = as<Imf::CompressionAttribute>(a)) {
      for (const CodecName& codec : kCodecs)
        if (codec.compression == c->value()) metadata->strings.emplace_back(name, codec.name);
    } else if (auto* ch = as<Imf::ChromaticitiesAttribute>(a)) {
      const Imf::Chromaticities& v = ch->value();
      const float xy[8] = {v.red.x,  v.red.y,  v.green.x, v.green.y,
                           v.blue.x, v.blue.y, v.white.x, v.white.y};
      pushFloats(metadata, name, xy, 8);
    } else if (auto* v2 = as<Imf::V2fAttribute>(a)) {
      pushFloats(metadata, name, &v2->value().x, 2);
    } else if (auto* v3 = as<Imf::V3fAttribute>(a)) {
      pushFloats(metadata, name, &v3->value().x, 3);
    } else if (auto* m3 = as<Imf::M33fAttribute>(a)) {
      pushFloats(metadata, name, m3->value()[0], 9);
    } else if (auto* m4 = as<Imf::M44fAttribute>(a)) {
      pushFloats(metadata, name, m4->value()[0], 16);
    }
  }
}

// OpenEXR compresses and decompresses blocks of scanlines on its global thread pool: as many
// threads as cores (OpenImageIO's default too), but none for images of a few blocks, such as the
// 1x1 film of a quick check, so that they start no threads. Returns the count to open a file with.
int exrThreads(int64_t height) {
  const int threads = int(std::min<int64_t>(std::thread::hardware_concurrency(), height / 32));
  if (threads <= 1) return 0;
  if (Imf::globalThreadCount() < threads) Imf::setGlobalThreadCount(threads);
  return threads;
}

}  // namespace

bool isExrCompression(const std::string& compression) {
  const size_t colon = compression.find(':');
  const std::string base = compression.substr(0, colon);
  const bool known = std::any_of(kCodecs.begin(), kCodecs.end(),
                                 [&](const CodecName& c) { return base == c.name; });
  if (!known || colon == std::string::npos) return known;
  // Only the DWA codecs take a quality suffix ("dwaa:45").
  const std::string level = compression.substr(colon + 1);
  return (base == "dwaa" || base == "dwab") && !level.empty() &&
         std::all_of(level.begin(), level.end(), [](char ch) { return ch >= '0' && ch <= '9'; });
}

bool hasExrMagic(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char magic[4] = {};
  in.read(reinterpret_cast<char*>(magic), 4);
  return in && magic[0] == 0x76 && magic[1] == 0x2f && magic[2] == 0x31 && magic[3] == 0x01;
}

void writeExrFile(const std::string& path, const ImageBuffer& image, const ImageMetadata& metadata,
                  const ExrOptions& options, const std::optional<Chromaticities>& chromaticities) {
  const size_t colon = options.compression.find(':');
  const std::string codec = options.compression.substr(0, colon);
  Imf::Compression compression = Imf::ZIP_COMPRESSION;
  for (const CodecName& c : kCodecs)
    if (codec == c.name) compression = c.compression;

  // Data window inside the display window, so crop renders composite in place.
  const Imath::Box2i display(Imath::V2i(0, 0),
                             Imath::V2i(image.displayWidth() - 1, image.displayHeight() - 1));
  const Imath::Box2i data(
      Imath::V2i(image.xOffset, image.yOffset),
      Imath::V2i(image.xOffset + image.width - 1, image.yOffset + image.height - 1));
  Imf::Header header(display, data, 1.f, Imath::V2f(0, 0), 1.f, Imf::INCREASING_Y, compression);
  if (codec == "dwaa" || codec == "dwab") {
    const float level = colon == std::string::npos
                            ? header.dwaCompressionLevel()
                            : std::stof(options.compression.substr(colon + 1));
    header.dwaCompressionLevel() = level;
    header.insert("dwaCompressionLevel", Imf::FloatAttribute(level));
  }
  header.insert("candela:colorSpace", Imf::StringAttribute(options.colorSpace));
  if (chromaticities) {
    const auto& xy = chromaticities->xy;
    header.insert("chromaticities", Imf::ChromaticitiesAttribute(Imf::Chromaticities(
                                        Imath::V2f(xy[0], xy[1]), Imath::V2f(xy[2], xy[3]),
                                        Imath::V2f(xy[4], xy[5]), Imath::V2f(xy[6], xy[7]))));
  }
  for (const auto& [name, value] : metadata.strings)
    header.insert(exrName(name), Imf::StringAttribute(value));
  for (const auto& [name, value] : metadata.floats)
    header.insert(exrName(name), Imf::FloatAttribute(value));
  for (const auto& [name, value] : metadata.ints)
    header.insert(exrName(name), Imf::IntAttribute(value));

  // Float channels are written from the image in place; half ones from a converted copy (OpenEXR
  // converts pixel types when reading, not when writing), rounded to nearest as Imath's half does.
  const size_t nChannels = image.channels.size(), nPixels = image.pixelCount();
  std::vector<std::vector<Imath::half>> halves;
  halves.reserve(nChannels);
  Imf::FrameBuffer frame;
  for (size_t c = 0; c < nChannels; ++c) {
    const std::string& name = image.channels[c];
    if (options.half && !keepsFloat(name)) {
      std::vector<Imath::half>& plane = halves.emplace_back(nPixels);
      for (size_t i = 0; i < nPixels; ++i) plane[i] = Imath::half(image.data[i * nChannels + c]);
      header.channels().insert(name, Imf::Channel(Imf::HALF));
      frame.insert(name, Imf::Slice::Make(Imf::HALF, plane.data(), data, sizeof(Imath::half),
                                          sizeof(Imath::half) * size_t(image.width)));
    } else {
      const size_t xStride = nChannels * sizeof(float);
      header.channels().insert(name, Imf::Channel(Imf::FLOAT));
      frame.insert(name, Imf::Slice::Make(Imf::FLOAT, image.data.data() + c, data, xStride,
                                          xStride * size_t(image.width)));
    }
  }
  Imf::OutputFile file(path.c_str(), header, exrThreads(image.height));
  file.setFrameBuffer(frame);
  file.writePixels(image.height);
}

DecodedImage readExrFile(const std::string& path, ImageMetadata* metadata) {
  // The height is not known before the header is read: files are read with every core.
  Imf::InputFile file(path.c_str(), exrThreads(std::numeric_limits<int>::max()));
  const Imf::Header& header = file.header();
  const Imath::Box2i data = header.dataWindow(), display = header.displayWindow();
  // Sizes in 64 bits: a corrupt header's windows may span more than an int holds.
  auto extent = [](int lo, int hi) { return int64_t(hi) - int64_t(lo) + 1; };
  const int64_t sizes[4] = {extent(data.min.x, data.max.x), extent(data.min.y, data.max.y),
                            extent(display.min.x, display.max.x),
                            extent(display.min.y, display.max.y)};
  for (int64_t size : sizes)
    if (size <= 0 || size > std::numeric_limits<int>::max())
      throw std::runtime_error("unsupported image dimensions");
  DecodedImage decoded;
  ImageBuffer& image = decoded.image;
  image.width = int(sizes[0]);
  image.height = int(sizes[1]);
  image.xOffset = data.min.x;
  image.yOffset = data.min.y;
  image.fullWidth = int(sizes[2]);
  image.fullHeight = int(sizes[3]);

  bool allUint = true;
  for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
    if (it.channel().xSampling != 1 || it.channel().ySampling != 1)
      throw std::runtime_error(std::string("channel '") + it.name() +
                               "' is subsampled, which candela does not read");
    image.channels.emplace_back(it.name());
    allUint = allUint && it.channel().type == Imf::UINT;
  }
  if (image.channels.empty()) throw std::runtime_error("no channels");
  std::stable_sort(image.channels.begin(), image.channels.end(),
                   [](const std::string& a, const std::string& b) {
                     return channelOrderKey(a) < channelOrderKey(b);
                   });
  decoded.integerPixels = allUint;

  image.data.assign(image.pixelCount() * image.channels.size(), 0.f);
  const size_t xStride = image.channels.size() * sizeof(float);
  const size_t yStride = xStride * size_t(image.width);
  Imf::FrameBuffer frame;
  for (size_t c = 0; c < image.channels.size(); ++c)
    frame.insert(image.channels[c],
                 Imf::Slice::Make(Imf::FLOAT, image.data.data() + c, data, xStride, yStride));
  file.setFrameBuffer(frame);
  file.readPixels(data.min.y, data.max.y);
  if (metadata) collectMetadata(header, metadata);
  return decoded;
}

}  // namespace candela
