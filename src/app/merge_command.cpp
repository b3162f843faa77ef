#include "app/merge_command.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "app/error_log.h"
#include "app/piece_set.h"
#include "app/staged_files.h"
#include "core/error.h"
#include "film/error_metrics.h"
#include "film/film_sums.h"
#include "film/output/image_output.h"
#include "film/output/image_plugin.h"
#include "filters/box_filter.h"
#include "integrators/tile_grid.h"

namespace candela {

namespace {

namespace fs = std::filesystem;

struct MergeOptions {
  std::string outfile;
  std::vector<std::string> pieces;
  PieceExpectations expected;
  bool half = false;
  std::string compression;
  std::string errorLog, reference;
  bool quiet = false;
};

// Adds up what the pieces of a frame split by sample range hold into a film of the whole image,
// in the order of their first samples, and logs the error after each range when asked.
ImageBuffer addSampleRanges(const FramePieces& frame, ErrorLog* log,
                            const std::optional<ImageBuffer>& reference, const MergeOptions& o) {
  const RenderPiece& ref = frame.pieces.front()->info;
  Film film(ref.fullResolution, cropWindowForPixels(ref.region, ref.fullResolution),
            std::make_unique<BoxFilter>(Vector2f(0.5f, 0.5f)), o.outfile);
  film.setScale(ref.filmScale);
  unsigned aovs = 0;
  for (unsigned flag : {unsigned(kAovVariance), unsigned(kAovSamples)})
    if (frame.pieces.front()->image.channelIndex(aovChannelNames(flag).front()) >= 0) aovs |= flag;
  film.enableAovs(aovs);
  std::vector<const LoadedPiece*> order = frame.pieces;
  std::stable_sort(order.begin(), order.end(), [](const LoadedPiece* a, const LoadedPiece* b) {
    return a->info.samples->first < b->info.samples->first;
  });
  PassReport pass;
  for (size_t i = 0; i < order.size(); ++i) {
    const LoadedPiece& piece = *order[i];
    try {
      addFilmSums(piece.image, film);
    } catch (const std::invalid_argument& e) {
      throw FileError(piece.path, std::string("cannot add its pixels' sums: ") + e.what());
    }
    pass.seconds += piece.info.seconds;
    pass.total.rays.intersectionRays += piece.info.rays;
    const IndexRange& range = *piece.info.samples;
    const bool rangeDone = i + 1 == order.size() || !(*order[i + 1]->info.samples == range);
    if (!log || !rangeDone) continue;
    pass.spp = range.last + 1;
    try {
      log->append(pass,
                  reference ? compareToReference(film, *reference) : estimateFromVariance(film));
    } catch (const std::invalid_argument& e) {
      throw FileError(o.reference, e.what());
    }
    ++pass.pass;
  }
  return film.image();
}

// The tiles of a frame put together by the image plug-in (OpenImageIO's paste).
ImageBuffer pasteTiles(const FramePieces& frame) {
  const RenderPiece& ref = frame.pieces.front()->info;
  ImageBuffer canvas(ref.region.pMax.x - ref.region.pMin.x, ref.region.pMax.y - ref.region.pMin.y,
                     frame.pieces.front()->image.channels);
  canvas.xOffset = ref.region.pMin.x;
  canvas.yOffset = ref.region.pMin.y;
  canvas.fullWidth = ref.fullResolution.x;
  canvas.fullHeight = ref.fullResolution.y;
  std::vector<const ImageBuffer*> tiles;
  for (const LoadedPiece* p : frame.pieces) tiles.push_back(&p->image);
  std::string error;
  if (!imagePlugin().pasteTiles(tiles, &canvas, &error))
    throw std::runtime_error("candela merge: error: cannot assemble the tiles: " + error);
  return canvas;
}

// The output's EXR settings: the command line's, else what the pieces were written with.
ExrOptions exrOptionsOf(const LoadedPiece& piece, const MergeOptions& o) {
  const ImageMetadata& metadata = piece.metadata;
  ExrOptions exr;
  exr.half = o.half || piece.info.half;
  const std::string* compression = metadata.findString("compression");
  exr.compression = !o.compression.empty() ? o.compression : compression ? *compression : "zip";
  exr.colorSpace = piece.info.colorSpace;
  Chromaticities c;
  bool all = true;
  for (int i = 0; i < 8; ++i) {
    const float* v = metadata.findFloat("chromaticities[" + std::to_string(i) + "]");
    all = all && v;
    if (v) c.xy[size_t(i)] = *v;
  }
  if (all) exr.chromaticities = c;
  return exr;
}

int merge(const MergeOptions& o) {
  checkImagePath(o.outfile);
  std::vector<LoadedPiece> pieces;
  for (const std::string& path : o.pieces) {
    ImageMetadata meta;
    ImageBuffer image = readImage(path, &meta);
    RenderPiece info = readRenderPiece(path, image, meta);
    pieces.push_back({path, std::move(image), std::move(meta), std::move(info)});
  }
  const std::vector<FramePieces> frames = groupPieces(pieces, o.expected);
  for (const FramePieces& frame : frames)
    for (const LoadedPiece& piece : pieces) {
      std::error_code ec;
      const std::string target = framePath(o.outfile, frame.frame);
      if (fs::equivalent(fs::path(piece.path), fs::path(target), ec))
        throw FileError(target, "refusing to overwrite '" + piece.path + "', a piece to merge");
    }
  const bool bySample = bool(pieces.front().info.samples);
  if (!o.errorLog.empty() && !bySample)
    throw MergeRefusal("error: --error-log needs pieces split by --sample-range");
  if (!o.errorLog.empty() && frames.size() > 1)
    throw MergeRefusal("error: --error-log logs one frame; these pieces have " +
                       std::to_string(frames.size()));
  std::optional<ImageBuffer> reference;
  if (!o.reference.empty()) reference = readImage(o.reference);
  std::unique_ptr<ErrorLog> log;
  if (!o.errorLog.empty()) log = std::make_unique<ErrorLog>(o.errorLog);

  StagedFiles staged;
  for (const FramePieces& frame : frames) {
    const LoadedPiece& first = *frame.pieces.front();
    const RenderPiece& ref = first.info;
    const ImageBuffer image =
        bySample ? addSampleRanges(frame, log.get(), reference, o) : pasteTiles(frame);
    double seconds = 0;
    unsigned long long rays = 0;
    for (const LoadedPiece* p : frame.pieces) seconds += p->info.seconds, rays += p->info.rays;
    ImageMetadata meta;
    addRenderMetadata(ref.scene, ref.spp, ref.seed, seconds, rays, &meta);
    RenderPiece whole = ref;
    whole.tile = TileIndex{};
    whole.samples.reset();
    addPieceMetadata(whole, &meta);
    meta.ints.push_back({"candela:pieces", int(frame.pieces.size())});
    const std::string target = framePath(o.outfile, frame.frame);
    writeExr(staged.stage(target), image, meta, exrOptionsOf(first, o));
    if (!o.quiet)
      std::fprintf(stderr, "Merged frame %d from %zu pieces: %.2f s of rendering, %llu rays\n",
                   frame.frame, frame.pieces.size(), seconds, rays);
  }
  staged.commit(o.quiet);
  return 0;
}

}  // namespace

int runMerge(int argc, char** argv) {
  MergeOptions o;
  CLI::App app{
      "candela merge: assembles the pieces of a render split with --tile, --frames or "
      "--sample-range into the image one machine would have made (the same pixels; within float "
      "rounding for sample ranges). Refuses, writing nothing, pieces of different renders and "
      "missing or repeated ones.",
      "candela merge"};
  app.add_option("pieces", o.pieces, "The pieces' EXR files");
  app.add_option("-o,--outfile", o.outfile,
                 "Output EXR; frames other than 0 get -F before the extension, as candela names "
                 "them")
      ->required();
  int tiles = 0;
  std::string frames;
  app.add_option("--tiles", tiles, "Expect a grid of this many tiles")->check(CLI::PositiveNumber);
  app.add_option("--frames", frames, "Expect frames A to B (A-B or A), each complete");
  app.add_flag("--half", o.half, "Write half floats (default: as the pieces were asked for)");
  app.add_option("--compression", o.compression,
                 "EXR compression (default: the pieces'): zip, piz, dwaa, none...");
  app.add_option("--error-log", o.errorLog,
                 "For pieces split by --sample-range: append seconds,spp,rays,mse,... after each "
                 "range, the seconds and rays summed over the pieces merged so far");
  app.add_option("--reference", o.reference,
                 "Reference EXR for --error-log (default: the error estimated from the pixels' "
                 "variance)")
      ->check(CLI::ExistingFile);
  app.add_flag("-q,--quiet", o.quiet, "Say nothing unless something is wrong");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  if (tiles > 0) o.expected.tiles = tiles;
  if (!frames.empty() && !(o.expected.frames = parseIndexRange(frames))) {
    std::fprintf(stderr, "candela merge: error: --frames %s: expected A-B (or A), 0 <= A <= B\n",
                 frames.c_str());
    return 2;
  }
  if (!o.reference.empty() && o.errorLog.empty()) {
    std::fprintf(stderr, "candela merge: error: --reference is for --error-log\n");
    return 2;
  }
  try {
    return merge(o);
  } catch (const std::exception& e) {
    const std::string message = e.what();
    std::fprintf(stderr, "%s%s\n", message.rfind("error:", 0) == 0 ? "candela merge: " : "",
                 message.c_str());
    return 1;
  }
}

}  // namespace candela
