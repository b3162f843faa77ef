// The image plug-in (candela_oiio.so): ImageCodec on OpenImageIO. candela loads it with dlopen
// only when it needs a format other than OpenEXR (film/output/image_codec.h).
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <exception>

#include "film/output/image_codec.h"

namespace candela {
namespace {

// The header's scalar attributes, and float arrays of up to 16 values as "name[i]".
void collectMetadata(const OIIO::ImageSpec& spec, ImageMetadata* metadata) {
  for (const OIIO::ParamValue& p : spec.extra_attribs) {
    const std::string name = p.name().string();
    const OIIO::TypeDesc t = p.type();
    const int count = int(t.numelements()) * int(t.aggregate) * p.nvalues();
    if (t == OIIO::TypeString) {
      metadata->strings.emplace_back(name, p.get_string());
    } else if (t.basetype == OIIO::TypeDesc::FLOAT || t.basetype == OIIO::TypeDesc::HALF ||
               t.basetype == OIIO::TypeDesc::DOUBLE) {
      if (count == 1)
        metadata->floats.emplace_back(name, p.get_float());
      else if (count <= 16)
        for (int i = 0; i < count; ++i)
          metadata->floats.emplace_back(name + "[" + std::to_string(i) + "]",
                                        p.get_float_indexed(i));
    } else if (count == 1 &&
               (t.basetype == OIIO::TypeDesc::INT || t.basetype == OIIO::TypeDesc::UINT ||
                t.basetype == OIIO::TypeDesc::INT16 || t.basetype == OIIO::TypeDesc::UINT16 ||
                t.basetype == OIIO::TypeDesc::INT8 || t.basetype == OIIO::TypeDesc::UINT8)) {
      metadata->ints.emplace_back(name, p.get_int());
    }
  }
}

class OiioCodec final : public ImageCodec {
 public:
  bool read(const std::string& path, DecodedImage* out, ImageMetadata* metadata,
            std::string* error) const override {
    try {
      auto in = OIIO::ImageInput::open(path);
      if (!in) return fail(error, OIIO::geterror());
      const OIIO::ImageSpec& spec = in->spec();
      if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.depth != 1)
        return fail(error, "unsupported image dimensions");
      ImageBuffer& image = out->image;
      image.width = spec.width;
      image.height = spec.height;
      image.channels = spec.channelnames;
      image.channels.resize(size_t(spec.nchannels));
      image.xOffset = spec.x;
      image.yOffset = spec.y;
      image.fullWidth = spec.full_width;
      image.fullHeight = spec.full_height;
      image.data.assign(image.pixelCount() * size_t(spec.nchannels), 0.f);
      if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.data.data()))
        return fail(error, in->geterror());
      in->close();
      out->integerPixels = !spec.format.is_floating_point();
      if (metadata) collectMetadata(spec, metadata);
      return true;
    } catch (const std::exception& e) {
      return fail(error, e.what());
    }
  }

  bool writeSrgb8(const std::string& path, const std::string& format, int width, int height,
                  const unsigned char* rgb, std::string* error) const override {
    try {
      auto out = OIIO::ImageOutput::create(format);
      if (!out)
        return fail(error, "no image writer for format '" + format + "': " + OIIO::geterror());
      OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
      spec.attribute("oiio:ColorSpace", "sRGB");  // PNG gets an sRGB chunk
      if (format == "jpeg") spec.attribute("CompressionQuality", 95);
      if (!out->open(path, spec)) return fail(error, "cannot open for writing: " + out->geterror());
      const bool written = out->write_image(OIIO::TypeDesc::UINT8, rgb);
      std::string message = written ? "" : "cannot write image: " + out->geterror();
      if (!out->close() && written) message = "cannot finish writing image: " + out->geterror();
      return message.empty() || fail(error, message);
    } catch (const std::exception& e) {
      return fail(error, std::string("cannot write image: ") + e.what());
    }
  }

  bool pasteTiles(const std::vector<const ImageBuffer*>& tiles, ImageBuffer* canvas,
                  std::string* error) const override {
    try {
      const int nc = canvas->channelCount();
      if (!canvas->consistent()) return fail(error, "the canvas is inconsistent");
      // Both wrap candela's memory: nothing is copied but what paste copies.
      OIIO::ImageSpec spec(canvas->width, canvas->height, nc, OIIO::TypeDesc::FLOAT);
      spec.x = canvas->xOffset;
      spec.y = canvas->yOffset;
      spec.channelnames = canvas->channels;
      OIIO::ImageBuf target(spec, canvas->data.data());
      for (const ImageBuffer* tile : tiles) {
        if (tile->channels != canvas->channels || !tile->consistent())
          return fail(error, "a tile's channels are not the image's");
        if (tile->xOffset < canvas->xOffset || tile->yOffset < canvas->yOffset ||
            tile->xOffset + tile->width > canvas->xOffset + canvas->width ||
            tile->yOffset + tile->height > canvas->yOffset + canvas->height)
          return fail(error, "a tile lies outside the image");
        const OIIO::ImageSpec tileSpec(tile->width, tile->height, nc, OIIO::TypeDesc::FLOAT);
        // paste only reads the source.
        const OIIO::ImageBuf source(tileSpec, const_cast<float*>(tile->data.data()));
        // paste puts the source's pixel (0, 0) at (x, y) of the target's pixel coordinates.
        if (!OIIO::ImageBufAlgo::paste(target, tile->xOffset, tile->yOffset, 0, 0, source))
          return fail(error, target.geterror());
      }
      return true;
    } catch (const std::exception& e) {
      return fail(error, e.what());
    }
  }

 private:
  static bool fail(std::string* error, const std::string& message) {
    *error = message;
    return false;
  }
};

}  // namespace
}  // namespace candela

extern "C" __attribute__((visibility("default"))) const candela::ImageCodec* candela_image_codec(
    int version) {
  static const candela::OiioCodec codec;
  return version == candela::kImageCodecVersion ? &codec : nullptr;
}
