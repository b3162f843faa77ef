// The candela command line.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/render_piece.h"
#include "core/bounds.h"
#include "core/compatibility.h"

namespace candela {

struct CliOptions {
  std::vector<std::string> sceneFiles;  // "-" = standard input; none = standard input
  int nThreads = 0;
  int tileSize = 16;
  std::string outfile;  // overrides the Film's filename
  std::string preview;  // PNG/JPEG preview path; "" = next to the EXR; "none" = no preview
  int spp = 0;
  uint64_t seed = 0;
  std::optional<Bounds2f> cropWindow;
  bool quick = false, quiet = false, verbose = false, stats = false;
  std::string accelerator;      // overrides the scene's Accelerator; "" = the scene's (embree)
  std::string lightSampler;     // overrides the integrator's lightsamplestrategy; "" = the scene's
  bool guiding = false;         // turns on path's "guiding"
  std::string subdiv = "book";  // the code that refines "loopsubdiv": book or opensubdiv
  bool half = false;
  std::string dialect;                      // "" (detect), "pbrt-v2" or "pbrt-v3": material models
  std::string coatFresnel = "exact";        // plastic's coat: "exact" or "pbrt" (reversed indices)
  std::string hyperboloidNormal = "exact";  // "exact" or "pbrt" (the segment's direction as dp/dv)
  std::string turbulence = "mean";          // dropped octaves of wrinkled: "mean" or "pbrt"
  std::string compression;                  // "" = the Film's "compression" (default zip)
  std::string aovs;                         // "albedo,normal,..." added to the Film's "aovs"
  std::string ocioConfig, display = "sRGB", view = "Standard";
  std::string colorSpace;  // working and output space ("" = the config's scene_linear)
  std::string toneMap;     // preview tone map, overriding the scene's ToneMap statement
  // Error against run time: render in doubling passes, measure after each.
  std::string reference;   // EXR to compare with
  std::string errorLog;    // CSV: seconds,spp,...,relmse_ci95,relmse_predicted,samples
  double timeBudget = 0;   // seconds; 0 = none
  double targetError = 0;  // relMSE; 0 = none
  // Adaptive sampling: a pixel stops once its estimated relative error is at most this (0 = off),
  // after at least adaptiveMinSamples (0 = the default).
  double noiseThreshold = 0;
  int adaptiveMinSamples = 0;
  // A piece of a render split for a farm (`candela merge` assembles them): one tile of a grid,
  // some of the scene's frames, some of each pixel's samples.
  std::optional<TileIndex> tile;
  std::optional<IndexRange> frames, sampleRange;
  // --dialect, --coat-fresnel, --hyperboloid-normal, --turbulence and --subdiv as the build takes
  // them.
  CompatibilityProfile compatibility() const;
  bool progressive() const {
    return !reference.empty() || !errorLog.empty() || timeBudget > 0 || targetError > 0;
  }
};

// Parses argv; on --help or a usage error prints and returns the exit code to use (0 or 2).
std::optional<int> parseCommandLine(int argc, char** argv, CliOptions* options);

}  // namespace candela
