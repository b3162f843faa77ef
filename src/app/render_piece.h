// What one piece of a render split for a farm is (`--tile`, `--frames`, `--sample-range`), as its
// EXR's metadata records it, so that `candela merge` can check pieces belong together before it
// assembles them.
#pragma once

#include <optional>
#include <string>

#include "core/bounds.h"
#include "core/image_buffer.h"

namespace candela {

// first..last, both included (as Slurm writes array ranges).
struct IndexRange {
  int first = 0, last = 0;
  bool contains(int i) const { return i >= first && i <= last; }
  int size() const { return last - first + 1; }
  std::string str() const { return std::to_string(first) + "-" + std::to_string(last); }
  bool operator==(const IndexRange&) const = default;
};
// "A-B" or "A" with 0 <= A <= B; nullopt otherwise.
std::optional<IndexRange> parseIndexRange(const std::string& text);

// "I/N" with N >= 1 and 0 <= I < N; nullopt otherwise.
struct TileIndex {
  int index = 0, count = 1;
};
std::optional<TileIndex> parseTileIndex(const std::string& text);

struct RenderPiece {
  std::string scene;         // the scene files as named on the command line
  std::string sceneHash;     // of the scene files' contents (scene_hash.h)
  std::string imageOptions;  // the command-line options that change pixels (scene_hash.h)
  int spp = 0;
  std::string seed;        // 64-bit, as text
  int frame = 0;           // which WorldEnd of the scene, from 0
  TileIndex tile;          // 0/1 when the image was not split
  Bounds2i region;         // the pixels of the whole image, which the tiles cover together
  Bounds2i pixels;         // the piece's own pixels (its data window)
  Point2i fullResolution;  // the display window
  std::optional<IndexRange> samples;  // each pixel's sample indices, when split by sample
  float filmScale = 1;                // Film "scale", which merging sums needs
  bool half = false;                  // the EXR was asked for in half floats
  double seconds = 0;
  unsigned long long rays = 0;
  std::string colorSpace;  // candela:colorSpace
};

// The metadata every render's EXR has: Software, candela:scene, candela:spp, candela:seed,
// candela:renderSeconds, candela:rays and DateTime.
void addRenderMetadata(const std::string& scene, int spp, const std::string& seed, double seconds,
                       unsigned long long rays, ImageMetadata* metadata);

// The piece's own metadata keys (those addRenderMetadata does not write).
void addPieceMetadata(const RenderPiece& piece, ImageMetadata* metadata);

// Reads what a piece is from an image file's metadata and windows; a render without --tile is
// tile 0/1 of its own pixels. Throws FileError naming path for a file candela did not write or
// whose metadata is incomplete.
RenderPiece readRenderPiece(const std::string& path, const ImageBuffer& image,
                            const ImageMetadata& metadata);

}  // namespace candela
