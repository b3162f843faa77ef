#include "app/render_piece.h"

#include <charconv>
#include <ctime>
#include <sstream>

#include "core/error.h"

namespace candela {

namespace {

// A whole non-negative decimal number filling text.
std::optional<int> parseCount(std::string_view text) {
  int v = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || text.empty() || v < 0)
    return std::nullopt;
  return v;
}

std::string boundsText(const Bounds2i& b) {
  return std::to_string(b.pMin.x) + " " + std::to_string(b.pMin.y) + " " +
         std::to_string(b.pMax.x) + " " + std::to_string(b.pMax.y);
}

}  // namespace

std::optional<IndexRange> parseIndexRange(const std::string& text) {
  const size_t dash = text.find('-');
  auto a = parseCount(std::string_view(text).substr(0, dash));
  auto b = dash == std::string::npos ? a : parseCount(std::string_view(text).substr(dash + 1));
  if (!a || !b || *b < *a) return std::nullopt;
  return IndexRange{*a, *b};
}

std::optional<TileIndex> parseTileIndex(const std::string& text) {
  const size_t slash = text.find('/');
  if (slash == std::string::npos) return std::nullopt;
  auto i = parseCount(std::string_view(text).substr(0, slash));
  auto n = parseCount(std::string_view(text).substr(slash + 1));
  if (!i || !n || *n < 1 || *i >= *n) return std::nullopt;
  return TileIndex{*i, *n};
}

void addRenderMetadata(const std::string& scene, int spp, const std::string& seed, double seconds,
                       unsigned long long rays, ImageMetadata* m) {
  m->strings.push_back({"Software", std::string("candela ") + CANDELA_VERSION});
  m->strings.push_back({"candela:scene", scene});
  m->ints.push_back({"candela:spp", spp});
  m->strings.push_back({"candela:seed", seed});  // 64-bit: EXR has no such integer type
  m->floats.push_back({"candela:renderSeconds", float(seconds)});
  m->strings.push_back({"candela:rays", std::to_string(rays)});
  std::time_t now = std::time(nullptr);
  char date[32];
  std::strftime(date, sizeof date, "%Y:%m:%d %H:%M:%S", std::localtime(&now));
  m->strings.push_back({"DateTime", date});
}

void addPieceMetadata(const RenderPiece& piece, ImageMetadata* m) {
  m->strings.push_back({"candela:sceneHash", piece.sceneHash});
  m->strings.push_back({"candela:imageOptions", piece.imageOptions});
  m->ints.push_back({"candela:frame", piece.frame});
  m->strings.push_back(
      {"candela:tile", std::to_string(piece.tile.index) + "/" + std::to_string(piece.tile.count)});
  m->strings.push_back({"candela:imageRegion", boundsText(piece.region)});
  if (piece.samples) {
    m->strings.push_back({"candela:sampleRange", piece.samples->str()});
    m->floats.push_back({"candela:filmScale", piece.filmScale});
  }
  m->ints.push_back({"candela:half", piece.half ? 1 : 0});
}

RenderPiece readRenderPiece(const std::string& path, const ImageBuffer& image,
                            const ImageMetadata& m) {
  auto missing = [&](const std::string& key) {
    return FileError(path, "not a candela render piece: its metadata has no valid '" + key + "'");
  };
  auto text = [&](const std::string& key) {
    const std::string* s = m.findString(key);
    if (!s) throw missing(key);
    return *s;
  };
  RenderPiece p;
  p.scene = text("candela:scene");
  p.sceneHash = text("candela:sceneHash");
  p.imageOptions = text("candela:imageOptions");
  p.seed = text("candela:seed");
  p.colorSpace = text("candela:colorSpace");
  const int* spp = m.findInt("candela:spp");
  const int* frame = m.findInt("candela:frame");
  const float* seconds = m.findFloat("candela:renderSeconds");
  if (!spp) throw missing("candela:spp");
  if (!frame) throw missing("candela:frame");
  if (!seconds) throw missing("candela:renderSeconds");
  p.spp = *spp;
  p.frame = *frame;
  p.seconds = *seconds;
  try {
    p.rays = std::stoull(text("candela:rays"));
  } catch (const std::logic_error&) {
    throw missing("candela:rays");
  }
  p.pixels = Bounds2i(Point2i(image.xOffset, image.yOffset),
                      Point2i(image.xOffset + image.width, image.yOffset + image.height));
  p.fullResolution = Point2i(image.displayWidth(), image.displayHeight());
  p.region = p.pixels;
  if (const std::string* region = m.findString("candela:imageRegion")) {
    std::istringstream in(*region);
    Bounds2i b;
    if (!(in >> b.pMin.x >> b.pMin.y >> b.pMax.x >> b.pMax.y) || b.empty())
      throw missing("candela:imageRegion");
    p.region = b;
  }
  if (const std::string* tile = m.findString("candela:tile")) {
    auto t = parseTileIndex(*tile);
    if (!t) throw missing("candela:tile");
    p.tile = *t;
  }
  if (const std::string* range = m.findString("candela:sampleRange")) {
    p.samples = parseIndexRange(*range);
    const float* scale = m.findFloat("candela:filmScale");
    if (!p.samples) throw missing("candela:sampleRange");
    if (!scale) throw missing("candela:filmScale");
    p.filmScale = *scale;
  }
  if (const int* half = m.findInt("candela:half")) p.half = *half != 0;
  return p;
}

}  // namespace candela
