// The candela command: parse scene files, render each WorldEnd, write EXR and a preview.
// Exit codes: 0 success, 1 scene or render error, 2 usage error.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <new>
#include <string>

#include "accel/embree/embree_device.h"
#include "app/cli_options.h"
#include "app/compare_command.h"
#include "app/error_log.h"
#include "app/frame_writer.h"
#include "app/merge_command.h"
#include "app/render_piece.h"
#include "app/sample_range.h"
#include "app/scene_hash.h"
#include "assembly/render_job.h"
#include "core/interrupt.h"
#include "film/error_metrics.h"
#include "film/output/image_output.h"
#include "film/output/texture_loader.h"
#include "integrators/pixel_sample_integrator.h"
#include "integrators/progressive_render.h"
#include "parser/parser.h"
#include "parser/scene_builder.h"

using namespace candela;

namespace {

void printWarning(const FileLoc& loc, const std::string& message) {
  std::fprintf(stderr, "%s: warning: %s\n", loc.str().c_str(), message.c_str());
}

// The Film's adaptive sampling with the command line's options over it.
AdaptiveSampling adaptiveSampling(const RenderJob& job, const CliOptions& cli) {
  AdaptiveSampling a = job.adaptive;
  if (cli.noiseThreshold > 0) a.noiseThreshold = cli.noiseThreshold;
  if (cli.adaptiveMinSamples > 0) a.minSamples = cli.adaptiveMinSamples;
  return a;
}

// Doubling passes with the error after each (against --reference, or estimated from the image's
// own variance), the stop conditions, and what the EXR metadata should say about them.
ProgressiveResult renderProgressively(RenderJob& job, const CliOptions& cli,
                                      const RenderOptions& options,
                                      const AdaptiveSampling& adaptive, ImageMetadata* metadata) {
  std::optional<ImageBuffer> reference;
  if (!cli.reference.empty()) reference = readImage(cli.reference);
  std::unique_ptr<ErrorLog> log;
  if (!cli.errorLog.empty()) log = std::make_unique<ErrorLog>(cli.errorLog);
  ErrorMetrics last;
  ProgressiveOptions po;
  po.render = options;
  po.adaptive = adaptive;
  po.timeBudget = cli.timeBudget;
  po.afterPass = [&](const PassReport& pass) {
    try {
      last =
          reference ? compareToReference(*job.film, *reference) : estimateFromVariance(*job.film);
    } catch (const std::invalid_argument& e) {
      throw FileError(cli.reference, e.what());
    }
    if (log) log->append(pass, last);
    if (!cli.quiet)
      std::fprintf(stderr, "  relMSE %.4g (95%% CI +-%.2g)%s\n", last.relmse, last.relmseCi95,
                   reference ? "" : " estimated from variance");
    return !(cli.targetError > 0 && last.relmse <= cli.targetError);
  };
  ProgressiveResult pr = renderJob(job, po);
  metadata->strings.push_back({"candela:stopReason", stopReasonName(pr.reason)});
  metadata->ints.push_back({"candela:passes", pr.passes});
  if (cli.timeBudget > 0) metadata->floats.push_back({"candela:timeBudget", float(cli.timeBudget)});
  if (cli.targetError > 0)
    metadata->floats.push_back({"candela:targetError", float(cli.targetError)});
  metadata->floats.push_back({"candela:relmse", float(last.relmse)});
  metadata->strings.push_back(
      {"candela:relmseSource", reference ? std::string("reference ").append(cli.reference)
                                         : std::string("variance estimate")});
  return pr;
}

// Files the render reads, which no output may overwrite.
using InputFiles = std::vector<std::string>;

void renderFrame(const SceneDescription& desc, const CliOptions& cli, const EmbreeDevice& device,
                 FrameWriter& writer, int frameIndex, InputFiles& inputs,
                 const std::string& sceneHash) {
  BuildOptions build;
  build.seed = cli.seed;
  build.sppOverride = cli.spp;
  build.cropWindow = cli.cropWindow;
  if (cli.tile) build.tileIndex = cli.tile->index, build.tileCount = cli.tile->count;
  build.quick = cli.quick;
  build.accelerator = cli.accelerator;
  build.lightSampler = cli.lightSampler;
  build.guiding = cli.guiding;
  build.compatibility = cli.compatibility();
  build.aovs = parseAovList(cli.aovs, FileLoc{"--aov", 0, 0});
  build.colorMatrix = writer.workingSpaceMatrix();
  build.loadImage = [&writer, &inputs](const std::string& path, const std::string& colorSpace) {
    inputs.push_back(path);
    const ColorManagement& cm = writer.colorManagement();
    std::string from = colorSpace;
    if (from == kSrgbEncoded) from = defaultTextureColorSpace(true, cm);
    if (from == kStoredLinear) from = defaultTextureColorSpace(false, cm);
    return loadTextureImage(path, from, cm, writer.workingSpace());
  };
  if (!cli.quiet) build.warn = printWarning;
  build.nThreads = cli.nThreads;
  build.showProgress = !cli.quiet;
  RenderJob job = buildRenderJob(desc, build, device);
  // The variance estimate needs each pixel's own samples to carry all of its light; splatted
  // light (bdpt, light tracing, Metropolis) and photon densities (sppm) are not in them, so a
  // target could never be met, or would be met too early.
  const PixelLight pixelLight = job.integrator->pixelLight();
  if (cli.targetError > 0 && cli.reference.empty() && pixelLight != PixelLight::OwnSamples)
    throw std::runtime_error(
        "--target-error without --reference estimates the error from each pixel's variance, "
        "which this scene's integrator does not keep (its light is splatted or gathered from "
        "photons): give --reference, or --time-budget");
  const AdaptiveSampling adaptive = adaptiveSampling(job, cli);
  // Each pixel's decisions need all of its earlier samples.
  if (adaptive.enabled() && cli.sampleRange)
    throw std::runtime_error(
        "--sample-range cannot be combined with adaptive sampling (--noise-threshold or the "
        "Film's \"noisethreshold\"): a pixel's decisions need all of its earlier samples "
        "(split the render with --tile instead)");
  if (cli.sampleRange) checkSampleRange(job, *cli.sampleRange);
  if (cli.tile && cli.tile->count > 1 && !cli.quiet && pixelLight != PixelLight::OwnSamples)
    std::fprintf(stderr,
                 "candela: warning: --tile: this scene's integrator spreads each sample's light "
                 "across the image, so each tile does much of the whole image's work (its pixels "
                 "are still the whole render's)\n");
  if (cli.stats) std::fprintf(stderr, "%s", job.stats.report().c_str());
  writer.checkOutputs(job.film->filename(), frameIndex, inputs);

  RenderOptions options;
  options.nThreads = cli.nThreads;
  options.tileSize = cli.tileSize;
  options.quiet = cli.quiet;
  if (cli.sampleRange) {
    options.firstSample = cli.sampleRange->first;
    options.endSample = cli.sampleRange->last + 1;
  }
  ImageMetadata extra;
  ProgressiveResult pr;
  if (cli.progressive()) {
    pr = renderProgressively(job, cli, options, adaptive, &extra);
  } else {
    ProgressiveOptions po;
    po.render = options;
    po.adaptive = adaptive;
    pr = renderJob(job, po);
  }
  if (adaptive.enabled()) {
    extra.floats.push_back({"candela:noiseThreshold", float(adaptive.noiseThreshold)});
    if (!cli.progressive()) {  // else renderProgressively records them
      extra.strings.push_back({"candela:stopReason", stopReasonName(pr.reason)});
      extra.ints.push_back({"candela:passes", pr.passes});
    }
  }
  const RenderResult& result = pr.total;
  const int spp = pr.spp;
  // What the integrator or renderer built (photon maps; the irradiance cache, while rendering).
  if (cli.stats) std::fprintf(stderr, "%s", job.integrator->statsReport().c_str());
  if (!cli.quiet) {
    uint64_t rays = result.rays.intersectionRays + result.rays.shadowRays;
    std::fprintf(stderr,
                 "Render time %.2fs, %llu samples (%.3g samples/s), %llu rays (%.3g rays/s: "
                 "%llu closest-hit, %llu shadow)\n",
                 result.seconds, (unsigned long long)result.samples,
                 result.samples / std::max(result.seconds, 1e-9), (unsigned long long)rays,
                 rays / std::max(result.seconds, 1e-9),
                 (unsigned long long)result.rays.intersectionRays,
                 (unsigned long long)result.rays.shadowRays);
  }
  if (result.nonFiniteSamples > 0 && (!cli.quiet || cli.stats)) {
    // Where the first one was, and the options that render just that pixel up to it.
    std::string where;
    if (const auto& f = result.firstNonFinite) {
      const Point2i res = job.film->fullResolution();
      char buf[256];
      std::snprintf(buf, sizeof buf,
                    "; the first at pixel (%d, %d), sample %d (to render that pixel alone, with "
                    "the same samples: --cropwindow %.9g %.9g %.9g %.9g)",
                    f->pixel.x, f->pixel.y, f->index, double(f->pixel.x) / res.x,
                    double(f->pixel.x + 1) / res.x, double(f->pixel.y) / res.y,
                    double(f->pixel.y + 1) / res.y);
      where = buf;
    }
    std::fprintf(stderr, "warning: %llu samples had NaN or infinite radiance and were dropped%s\n",
                 (unsigned long long)result.nonFiniteSamples, where.c_str());
  }
  ExrOptions exr;
  exr.compression = cli.compression.empty() ? job.exrCompression : cli.compression;
  exr.half = cli.half || job.exrHalf;
  RenderPiece piece;
  piece.sceneHash = sceneHash;
  piece.imageOptions = imageOptionsText(cli, exr.half);
  piece.frame = frameIndex;
  if (cli.tile) piece.tile = *cli.tile;
  piece.region = job.imageRegion;
  piece.samples = cli.sampleRange;
  piece.filmScale = job.film->scale();
  piece.half = exr.half;
  addPieceMetadata(piece, &extra);
  // The sums need every bit of their floats; `candela merge` writes the half image.
  if (cli.sampleRange) exr.half = false;
  writer.write(*job.film, desc, spp, result, frameIndex, extra, exr);
  std::vector<NamedImage> images = job.integrator->extraImages(*job.film);
  if (!images.empty()) writer.writeBeside(*job.film, frameIndex, images, exr);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "merge") return runMerge(argc - 1, argv + 1);
  if (argc > 1 && std::string(argv[1]) == "compare") return runCompare(argc - 1, argv + 1);
  CliOptions cli;
  if (auto code = parseCommandLine(argc, argv, &cli)) return *code;
  if (cli.sceneFiles.empty()) cli.sceneFiles.push_back("-");
  installInterruptHandlers();
  try {
    EmbreeDevice device;
    FrameWriter writer(cli);
    // Every file is parsed before any frame renders, so that an error anywhere in it stops the
    // run before work is done (as pbrt-v4 does); frames are then rendered in order, and their
    // images written only when all have succeeded.
    std::vector<SceneDescription> frames;
    SceneBuilder builder(
        [&](SceneDescription&& desc) { frames.push_back(std::move(desc)); },
        cli.quiet ? SceneBuilder::WarningCallback() : SceneBuilder::WarningCallback(printWarning));
    SceneHash hash;
    for (const std::string& file : cli.sceneFiles) {
      if (file == "-") {
        // Read here rather than by parseFile, so that its text can be hashed too.
        std::string text((std::istreambuf_iterator<char>(std::cin)),
                         std::istreambuf_iterator<char>());
        hash.add(text);
        parseString(text, file, builder);
      } else {
        parseFile(file, builder);
        hash.addFile(file);
      }
    }
    builder.endOfInput(FileLoc{cli.sceneFiles.back(), 0, 0});
    if (frames.empty()) {
      std::fprintf(stderr,
                   "candela: error: the scene has no WorldBegin/WorldEnd: nothing to render\n");
      return 1;
    }
    if (cli.frames && cli.frames->last >= int(frames.size())) {
      std::fprintf(stderr, "candela: error: --frames %s: the scene has %zu frame%s (0-%zu)\n",
                   cli.frames->str().c_str(), frames.size(), frames.size() == 1 ? "" : "s",
                   frames.size() - 1);
      return 1;
    }
    InputFiles inputs;
    for (const std::string& file : cli.sceneFiles)
      if (file != "-") inputs.push_back(file);
    if (!cli.reference.empty()) inputs.push_back(cli.reference);
    for (size_t i = 0; i < frames.size(); ++i) {
      if (cli.frames && !cli.frames->contains(int(i))) continue;
      throwIfInterrupted();
      renderFrame(frames[i], cli, device, writer, int(i), inputs, hash.hex());
    }
    throwIfInterrupted();
    writer.commit();
  } catch (const Interrupted& e) {
    // The writer's staged files are gone with it; nothing was renamed.
    std::fprintf(stderr, "candela: %s: stopped, nothing written\n", e.what());
    return 128 + e.signal();
  } catch (const std::bad_alloc&) {
    // The scene asked for more than the machine has (the factories refuse the sizes they can
    // foresee: films, subdivision levels).
    std::fprintf(stderr, "candela: error: out of memory\n");
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
