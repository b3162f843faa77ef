// The candela command line.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/bounds.h"

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
  bool half = false;
  std::string compression = "zip";
  std::string ocioConfig, display = "sRGB", view = "Standard";
};

// Parses argv; on --help or a usage error prints and returns the exit code to use (0 or 2).
std::optional<int> parseCommandLine(int argc, char** argv, CliOptions* options);

}  // namespace candela
