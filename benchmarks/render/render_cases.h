// The render benchmark's cases: a scene file and the statements that set its sampler, filter and
// integrator for the benchmark (inserted before its WorldBegin; a later statement replaces an
// earlier one), so that the example scenes stay as they are.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "assembly/render_job.h"

namespace candela::bench {

struct RenderCase {
  std::string name;
  std::string scene;      // path of the .pbrt file
  std::string overrides;  // statements before WorldBegin; empty: the file as it is
};

// The cases: the Cornell box at 256 x 256, 64 spp, path tracing to depth 8, box filter,
// with the Halton and the random sampler; and a diffuse box with a sphere, 64 x 64, 256 spp.
// sourceDir: the repository root.
std::vector<RenderCase> standardCases(const std::string& sourceDir);

// The job of a case's first frame with this seed. Throws on errors (SceneError naming the file).
std::unique_ptr<RenderJob> buildCase(const RenderCase& c, uint64_t seed,
                                     const EmbreeDevice& device);

}  // namespace candela::bench
