// Test helper: a scene given as text, parsed, built and rendered in-process.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "assembly/render_job.h"
#include "integrators/pixel_sample_integrator.h"
#include "integrators/progressive_render.h"

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

// Sample ranges rendered by hand with a job's pixel-sample integrator (its camera and sampler, no
// Volume regions' integrator), into any scene and film: for tests that take passes themselves.
class PixelPasses {
 public:
  explicit PixelPasses(RenderJob& job);  // fails the test unless the job's is one
  RenderResult render(const Scene& scene, Film& film, const RenderOptions& options) const;
  RenderPass pass(const Scene& scene, Film& film) const;

 private:
  RenderJob& job_;
  PixelSampleIntegrator* integrator_;
};

}  // namespace candela::test
