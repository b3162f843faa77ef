// Which render pieces `candela merge` was given, checked to make up whole images before anything
// is assembled: one scene, seed, sample count, resolution, image region and grid; every tile of
// every frame present once (or, split by sample range, with every sample exactly once); each
// piece's pixels those of its tile.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/render_piece.h"
#include "core/image_buffer.h"

namespace candela {

struct LoadedPiece {
  std::string path;
  ImageBuffer image;
  ImageMetadata metadata;  // the file's header
  RenderPiece info;
};

// What the caller knows the pieces should make (from `candela merge --tiles N --frames A-B`).
struct PieceExpectations {
  std::optional<int> tiles;
  std::optional<IndexRange> frames;
};

// One output image: the pieces of one frame, by tile, then by first sample.
struct FramePieces {
  int frame = 0;
  std::vector<const LoadedPiece*> pieces;
};

// A set of pieces that cannot be merged; the message names the file(s) and what is wrong, or
// lists every missing piece.
class MergeRefusal : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The pieces grouped by frame (in frame order). Throws MergeRefusal.
std::vector<FramePieces> groupPieces(const std::vector<LoadedPiece>& pieces,
                                     const PieceExpectations& expected);

}  // namespace candela
