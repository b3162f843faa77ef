// Test helper: a scene given as text, parsed, built and rendered in-process.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "assembly/render_job.h"
#include "renderers/sampler_renderer.h"

namespace candela::test {

struct RenderedScene {
  std::vector<RenderJob> jobs;  // one per WorldEnd
  std::vector<RenderResult> results;
  RenderJob& job() { return jobs.front(); }
  const Film& film() const { return *jobs.front().film; }
};

struct TestRenderOptions {
  BuildOptions build;
  RenderOptions render{0, 16, true};
};

// scenes/cornell-box at resolution x resolution, with its SurfaceIntegrator statement replaced
// by integrator (when not empty) and beforeWorldEnd inserted before its WorldEnd.
std::string cornellBoxText(int resolution, const std::string& integrator = "",
                           const std::string& beforeWorldEnd = "");

// scenes/NAME/NAME.pbrt (whose film is 256 x 256 and whose integrator statement is
// `SurfaceIntegrator "path" "integer maxdepth" [8]`) at resolution x resolution with that
// statement replaced by integrator, then each (from, to) of replace applied once.
std::string exampleSceneText(const std::string& name, const std::string& integrator, int resolution,
                             const std::vector<std::pair<std::string, std::string>>& replace = {});

// Throws what the parser or factories throw.
RenderedScene renderSceneText(const std::string& text, const TestRenderOptions& options = {});
// Only parse and build (no rendering).
RenderedScene buildSceneText(const std::string& text, const BuildOptions& options = {});

// The film's pixel values, row by row.
std::vector<Spectrum> pixelValues(const Film& film);

}  // namespace candela::test
