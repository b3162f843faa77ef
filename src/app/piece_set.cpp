#include "app/piece_set.h"

#include <algorithm>
#include <map>

#include "integrators/tile_grid.h"

namespace candela {

namespace {

std::string pixelsText(const Bounds2i& b) {
  return "pixels [" + std::to_string(b.pMin.x) + ", " + std::to_string(b.pMax.x) + ") x [" +
         std::to_string(b.pMin.y) + ", " + std::to_string(b.pMax.y) + ")";
}

std::string tileText(const TileIndex& t) {
  return "tile " + std::to_string(t.index) + "/" + std::to_string(t.count);
}

// "frame 2 tile 1/4 samples 64-127", leaving out what the render was not split by.
std::string pieceName(int frame, const TileIndex& tile, const std::optional<IndexRange>& samples) {
  // Built with append rather than " " + string: GCC 12 warns falsely (-Wrestrict) about that.
  std::string s = "frame " + std::to_string(frame);
  if (tile.count > 1) s.append(" ").append(tileText(tile));
  if (samples) s.append(" samples ").append(samples->str());
  return s;
}

std::string channelList(std::vector<std::string> channels) {
  std::sort(channels.begin(), channels.end());
  std::string s;
  for (const std::string& c : channels) s += (s.empty() ? "" : ",") + c;
  return s;
}

// Refuses a piece that is not of the same render as the first. Sample ranges are compared only
// as to whether there are any: they differ by design.
void checkSameRender(const LoadedPiece& piece, const LoadedPiece& first) {
  const RenderPiece &a = piece.info, &b = first.info;
  auto refuse = [&](bool differs, const std::string& what, const std::string& mine,
                    const std::string& theirs) {
    if (differs)
      throw MergeRefusal(piece.path + ": error: " + what + " " + mine + " (" + first.path + ": " +
                         theirs + ")");
  };
  auto resolution = [](const Point2i& r) {
    return std::to_string(r.x) + "x" + std::to_string(r.y);
  };
  auto split = [](const RenderPiece& p) {
    return p.samples ? "samples " + p.samples->str() : std::string("all samples");
  };
  // The most specific difference first: a piece with another resolution is also of another scene
  // or other options.
  refuse(a.seed != b.seed, "has another seed:", a.seed, b.seed);
  refuse(a.spp != b.spp, "has another sample count:", std::to_string(a.spp) + " per pixel",
         std::to_string(b.spp) + " per pixel");
  refuse(!(a.fullResolution == b.fullResolution),
         "has another resolution:", resolution(a.fullResolution), resolution(b.fullResolution));
  refuse(!(a.region == b.region),
         "covers another image region (crop window):", pixelsText(a.region), pixelsText(b.region));
  refuse(a.tile.count != b.tile.count, "is from another tile grid:", tileText(a.tile),
         tileText(b.tile));
  refuse(bool(a.samples) != bool(b.samples), "is split otherwise by sample:", split(a), split(b));
  refuse(channelList(piece.image.channels) != channelList(first.image.channels),
         "has other channels:", channelList(piece.image.channels),
         channelList(first.image.channels));
  refuse(a.colorSpace != b.colorSpace, "has another colour space:", a.colorSpace, b.colorSpace);
  refuse(a.imageOptions != b.imageOptions, "was rendered with other options:", a.imageOptions,
         b.imageOptions);
  refuse(a.sceneHash != b.sceneHash, "is from another scene: scene hash",
         a.sceneHash + " of '" + a.scene + "'", b.sceneHash + " of '" + b.scene + "'");
}

}  // namespace

std::vector<FramePieces> groupPieces(const std::vector<LoadedPiece>& pieces,
                                     const PieceExpectations& expected) {
  if (pieces.empty()) throw MergeRefusal("error: no pieces to merge");
  const LoadedPiece& first = pieces.front();
  const RenderPiece& ref = first.info;
  std::optional<TileGrid> grid;
  try {
    grid.emplace(ref.region, ref.tile.count);
  } catch (const std::invalid_argument& e) {
    throw MergeRefusal(first.path + ": error: " + tileText(ref.tile) + ": " + e.what());
  }
  std::map<int, std::vector<const LoadedPiece*>> byFrame;
  for (const LoadedPiece& piece : pieces) {
    const RenderPiece& p = piece.info;
    checkSameRender(piece, first);
    if (expected.tiles && p.tile.count != *expected.tiles)
      throw MergeRefusal(piece.path + ": error: " + tileText(p.tile) + ", but --tiles " +
                         std::to_string(*expected.tiles));
    if (expected.frames && !expected.frames->contains(p.frame))
      throw MergeRefusal(piece.path + ": error: frame " + std::to_string(p.frame) +
                         " is outside --frames " + expected.frames->str());
    if (!(p.pixels == grid->tile(p.tile.index)))
      throw MergeRefusal(piece.path + ": error: its " + pixelsText(p.pixels) +
                         " are not those of " + tileText(p.tile) + " (" +
                         pixelsText(grid->tile(p.tile.index)) + ")");
    if (p.samples && p.samples->last >= p.spp)
      throw MergeRefusal(piece.path + ": error: samples " + p.samples->str() + " beyond its " +
                         std::to_string(p.spp) + " samples per pixel");
    byFrame[p.frame].push_back(&piece);
  }
  if (expected.frames)
    for (int f = expected.frames->first; f <= expected.frames->last; ++f) byFrame[f];

  std::vector<std::string> missing;
  std::vector<FramePieces> frames;
  for (auto& [frame, list] : byFrame) {
    std::stable_sort(list.begin(), list.end(), [](const LoadedPiece* a, const LoadedPiece* b) {
      if (a->info.tile.index != b->info.tile.index) return a->info.tile.index < b->info.tile.index;
      return (a->info.samples ? a->info.samples->first : 0) <
             (b->info.samples ? b->info.samples->first : 0);
    });
    for (int t = 0; t < ref.tile.count; ++t) {
      const TileIndex tile{t, ref.tile.count};
      int next = 0;  // the first sample index no piece of this tile has taken yet
      const LoadedPiece* previous = nullptr;
      for (const LoadedPiece* piece : list) {
        if (piece->info.tile.index != t) continue;
        if (!ref.samples) {
          if (previous)
            throw MergeRefusal(piece->path + ": error: " + pieceName(frame, tile, std::nullopt) +
                               " again (" + previous->path + " has it)");
        } else {
          const IndexRange& r = *piece->info.samples;
          if (previous && r.first < next)
            throw MergeRefusal(piece->path + ": error: " + pieceName(frame, tile, r) +
                               " overlaps " + previous->path + "'s samples " +
                               previous->info.samples->str());
          if (r.first > next)
            missing.push_back(pieceName(frame, tile, IndexRange{next, r.first - 1}));
          next = r.last + 1;
        }
        previous = piece;
      }
      if (!ref.samples && !previous) missing.push_back(pieceName(frame, tile, std::nullopt));
      if (ref.samples && next < ref.spp)
        missing.push_back(pieceName(frame, tile, IndexRange{next, ref.spp - 1}));
    }
    frames.push_back(FramePieces{frame, list});
  }
  if (!missing.empty()) {
    std::string s;
    for (const std::string& m : missing) s += "\n  " + m;
    throw MergeRefusal("error: " + std::to_string(missing.size()) + " missing piece" +
                       (missing.size() == 1 ? "" : "s") + " (nothing written):" + s);
  }
  return frames;
}

}  // namespace candela
