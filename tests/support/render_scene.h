// Test helper: a scene given as text, parsed, built and rendered in-process.
#pragma once

#include <string>
#include <vector>

#include "renderers/sampler_renderer.h"
#include "scene/render_job.h"

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

// Throws what the parser or factories throw.
RenderedScene renderSceneText(const std::string& text, const TestRenderOptions& options = {});
// Only parse and build (no rendering).
RenderedScene buildSceneText(const std::string& text, const BuildOptions& options = {});

}  // namespace candela::test
