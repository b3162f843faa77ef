#include "app/cli_options.h"

#include <CLI/CLI.hpp>
#include <cstdio>

#include "accel/aggregate_factory.h"
#include "assembly/plugin_registry.h"
#include "lights/light_sampler.h"
#include "parser/scene_dialect.h"

namespace candela {

CompatibilityProfile CliOptions::compatibility() const {
  CompatibilityProfile p;
  p.dialect = parseSceneDialect(dialect);
  p.plasticCoat = coatFresnel == "pbrt" ? CoatFresnel::ReversedAsPbrt : CoatFresnel::Exact;
  p.hyperboloidNormal =
      hyperboloidNormal == "pbrt" ? HyperboloidNormal::SegmentAsPbrt : HyperboloidNormal::Exact;
  p.clampedOctaves = turbulence == "pbrt" ? ClampedOctaves::AsPbrt : ClampedOctaves::Mean;
  p.subdiv = subdiv == "opensubdiv" ? LoopProducer::OpenSubdiv : LoopProducer::Book;
  return p;
}

std::optional<int> parseCommandLine(int argc, char** argv, CliOptions* o) {
  CLI::App app{
      "candela: a physically based renderer for pbrt scene files.\n"
      "Renders each WorldEnd of the scene to a scene-linear OpenEXR file with a PNG "
      "preview.\n`candela merge -o out.exr pieces...` assembles the pieces of a render split "
      "with --tile, --frames or --sample-range (candela merge --help)."};
  app.add_option("scene", o->sceneFiles, "Scene files, read in order ('-' or none: stdin)");
  // Bounded so that a typo cannot ask the system for a hundred thousand threads (which crashed).
  app.add_option("--nthreads", o->nThreads, "Worker threads (default: all cores; at most 4096)")
      ->check(CLI::Range(0, 4096));
  app.add_option("--tile-size", o->tileSize, "Tile side in pixels (does not change the image)")
      ->check(CLI::PositiveNumber);
  app.add_option("-o,--outfile", o->outfile, "Output EXR (default: the Film's filename)");
  app.add_option("--preview", o->preview,
                 "Preview PNG/JPEG path (default: next to the EXR; 'none' for no preview)");
  app.add_option("--spp", o->spp, "Samples per pixel (overrides the Sampler's)")
      ->check(CLI::PositiveNumber);
  app.add_option("--seed", o->seed, "Random seed; the image is a pure function of it");
  std::vector<float> crop;
  app.add_option("--cropwindow", crop, "Render only x0 x1 y0 y1 of the image (NDC, 0..1)")
      ->expected(4);
  app.add_flag("--quick", o->quick, "Quarter resolution, an eighth of the samples");
  app.add_option("--accel", o->accelerator,
                 "Aggregate, overriding the scene's Accelerator (default: embree)")
      ->check(CLI::IsMember(acceleratorNames()));
  app.add_option("--light-sampler", o->lightSampler,
                 "How path, volpath and bdpt choose the light each sample goes to, overriding "
                 "the scene's lightsamplestrategy: uniform, power, spatial or bvh (a light tree)")
      ->check(CLI::IsMember(std::vector<std::string>(std::begin(kLightSampleStrategyNames),
                                                     std::end(kLightSampleStrategyNames))));
  app.add_flag("--guiding", o->guiding,
               "Path guiding for path: directions learned from the first quarter of the samples "
               "(the scene's \"bool guiding\")");
  app.add_option("--subdiv", o->subdiv,
                 "Code that refines loopsubdiv shapes: book (ours, default) or opensubdiv; the "
                 "surface is the same")
      ->check(CLI::IsMember({"book", "opensubdiv"}));
  app.add_option("--dialect", o->dialect,
                 "Scene format whose material models apply: pbrt-v2 or pbrt-v3 (default: "
                 "pbrt-v3 for scenes with Integrator or media statements, else pbrt-v2)")
      ->check(CLI::IsMember({"pbrt-v2", "pbrt-v3"}));
  app.add_option("--coat-fresnel", o->coatFresnel,
                 "plastic's coat Fresnel: exact (air outside, 1.5 inside) or pbrt (pbrt's "
                 "reversed indices, pbrt-v3 issue #210)")
      ->check(CLI::IsMember({"exact", "pbrt"}));
  app.add_option("--hyperboloid-normal", o->hyperboloidNormal,
                 "hyperboloid's normal: exact (the fitted surface's) or pbrt (from the p1-p2 "
                 "segment's direction, off the surface where the segment is not a ruling)")
      ->check(CLI::IsMember({"exact", "pbrt"}));
  app.add_option("--turbulence", o->turbulence,
                 "wrinkled's octaves dropped by the footprint: mean (their mean, once) or pbrt "
                 "(0.2 each, the partial octave's counted twice)")
      ->check(CLI::IsMember({"mean", "pbrt"}));
  app.add_flag("-q,--quiet", o->quiet, "No progress or statistics output");
  app.add_flag("-v,--verbose", o->verbose, "More detail");
  app.add_flag("--stats", o->stats, "Print what the scene built (geometry, Embree, lights...)");
  app.add_flag("--half", o->half, "Write half-float EXR channels (Z, P and samples stay float)");
  app.add_option("--aov", o->aovs,
                 "Extra EXR layers: albedo,normal,depth,position,variance,samples");
  app.add_option("--compression", o->compression, "EXR compression: zip, piz, dwaa, none")
      ->check(CLI::IsMember(
          {"zip", "zips", "piz", "dwaa", "dwab", "rle", "pxr24", "b44", "b44a", "none"}));
  app.add_option("--ocio", o->ocioConfig, "OpenColorIO config (default: $OCIO, then candela's)");
  app.add_option("--colorspace", o->colorSpace,
                 "Working and output colour space, e.g. acescg (default: scene_linear); input "
                 "colours are converted once at load");
  app.add_option("--display", o->display, "OCIO display for the preview");
  app.add_option("--tonemap", o->toneMap,
                 "Tone map the preview (never the EXR): maxwhite, contrast, highcontrast, "
                 "nonlinear");
  app.add_option("--view", o->view, "OCIO view for the preview");
  app.add_option("--reference", o->reference,
                 "Reference EXR: report the error against it after each pass")
      ->check(CLI::ExistingFile);
  app.add_option(
      "--error-log", o->errorLog,
      "Append seconds,spp,rays,mse,relmse,rmse,maxerr,relmse_ci95,relmse_predicted,samples "
      "after each pass (passes of 1, 2, 4, ... spp)");
  app.add_option("--time-budget", o->timeBudget, "Stop before a pass would end past this (s)")
      ->check(CLI::PositiveNumber);
  app.add_option("--target-error", o->targetError,
                 "Stop once relMSE is below this (estimated from the image's own variance "
                 "without --reference)")
      ->check(CLI::PositiveNumber);
  app.add_option("--noise-threshold", o->noiseThreshold,
                 "Adaptive sampling: a pixel stops taking samples once its relative error, "
                 "estimated from its own samples, is at most this (0.1 aims at an image relMSE "
                 "of about 0.01); the scene's samples per pixel stay the most any pixel takes")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--adaptive-min-samples", o->adaptiveMinSamples,
                 "Adaptive sampling: the samples every pixel takes before its noise is judged "
                 "(default 16)")
      ->check(CLI::PositiveNumber);
  std::string tile, frames, sampleRange;
  app.add_option("--tile", tile,
                 "Render tile I of a grid of N (I/N, I from 0 to N-1) that candela chooses over "
                 "the image; `candela merge` assembles the tiles");
  app.add_option("--frames", frames,
                 "Render only frames A to B (A-B or A, from 0) of a scene with several WorldEnds");
  app.add_option("--sample-range", sampleRange,
                 "Take only samples A to B (A-B, from 0) of each pixel; the EXR keeps the "
                 "pixels' sums for `candela merge`");
  std::string listKind, describeName;
  CLI::Option* list =
      app.add_option("--list-plugins", listKind,
                     "List every plug-in (or those of KIND: shape, material, texture, light, "
                     "integrator, ...) with its dialects, and exit")
          ->expected(0, 1);
  app.add_option("--describe", describeName,
                 "Print the parameters of the plug-in NAME (or KIND/NAME): type, default, rule "
                 "and dialect, and exit");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  if (list->count() > 0 || !describeName.empty()) {
    std::string text = list->count() > 0 ? listPlugins(listKind) : describePlugins(describeName);
    if (text.empty()) {
      std::string known;
      for (const PluginKind& k : pluginKinds())
        known += (known.empty() ? "" : ", ") + std::string(k.kind);
      std::fprintf(stderr, "candela: error: %s (kinds: %s)\n",
                   list->count() > 0 ? ("no plug-in kind '" + listKind + "'").c_str()
                                     : ("no plug-in called '" + describeName + "'").c_str(),
                   known.c_str());
      return 2;
    }
    std::fputs(text.c_str(), stdout);
    return 0;
  }
  if (crop.size() == 4) {
    for (float c : crop)
      if (!(c >= 0 && c <= 1)) {
        std::fprintf(stderr, "candela: error: --cropwindow values must lie in [0, 1]\n");
        return 2;
      }
    if (!(crop[0] < crop[1] && crop[2] < crop[3])) {
      std::fprintf(stderr, "candela: error: --cropwindow needs x0 < x1 and y0 < y1\n");
      return 2;
    }
    o->cropWindow = Bounds2f(Point2f(crop[0], crop[2]), Point2f(crop[1], crop[3]));
  }
  auto usage = [](const std::string& message) {
    std::fprintf(stderr, "candela: error: %s\n", message.c_str());
    return 2;
  };
  if (!tile.empty() && !(o->tile = parseTileIndex(tile)))
    return usage("--tile " + tile + ": expected I/N with N >= 1 and 0 <= I < N");
  if (!frames.empty() && !(o->frames = parseIndexRange(frames)))
    return usage("--frames " + frames + ": expected A-B (or A) with 0 <= A <= B");
  if (!sampleRange.empty() && !(o->sampleRange = parseIndexRange(sampleRange)))
    return usage("--sample-range " + sampleRange + ": expected A-B (or A) with 0 <= A <= B");
  if (o->adaptiveMinSamples > 0 && !(o->noiseThreshold > 0))
    return usage("--adaptive-min-samples needs --noise-threshold");
  // A stop condition per piece would give the pieces different sample counts.
  if ((o->tile || o->sampleRange) && o->progressive())
    return usage(std::string(o->tile ? "--tile" : "--sample-range") +
                 " renders a piece of a fixed sample count: it cannot be combined with "
                 "--reference, --error-log, --time-budget or --target-error (`candela merge "
                 "--error-log` logs the error of merged sample ranges)");
  return std::nullopt;
}

}  // namespace candela
