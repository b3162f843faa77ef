#include "support/render_scene.h"

#include "accel/embree/embree_device.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"
#include "support/test_device.h"

namespace candela::test {

namespace {

RenderedScene run(const std::string& text, const BuildOptions& build, const RenderOptions* render) {
  RenderedScene out;
  SceneBuilder builder(
      [&](SceneDescription&& desc) {
        out.jobs.push_back(buildRenderJob(desc, build, embreeDevice()));
        if (render) {
          RenderJob& job = out.jobs.back();
          ProgressiveOptions po;
          po.render = *render;
          out.results.push_back(renderJob(job, po).total);
        }
      },
      {});
  parseString(text, "test.pbrt", builder);
  builder.endOfInput(FileLoc{"test.pbrt", 0, 0});
  return out;
}
}  // namespace

RenderedScene renderSceneText(const std::string& text, const TestRenderOptions& options) {
  return run(text, options.build, &options.render);
}

RenderedScene buildSceneText(const std::string& text, const BuildOptions& options) {
  return run(text, options, nullptr);
}

}  // namespace candela::test
