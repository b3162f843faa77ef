#include "support/render_scene.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "accel/embree/embree_device.h"
#include "parser/parser.h"
#include "parser/scene_builder.h"
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

std::string cornellBoxText(int resolution, const std::string& integrator,
                           const std::string& beforeWorldEnd) {
  std::ifstream in(std::string(CANDELA_SOURCE_DIR) + "/scenes/cornell-box/cornell-box.pbrt");
  std::stringstream ss;
  ss << in.rdbuf();
  std::string s = ss.str();
  auto replace = [&](const std::string& from, const std::string& to) {
    size_t at = s.find(from);
    if (at == std::string::npos)
      throw std::logic_error("cornell-box.pbrt no longer has '" + from + "'");
    s.replace(at, from.size(), to);
  };
  // Built by appending: GCC 12 warns falsely (-Wrestrict) on "[" + std::string and on insert.
  std::string bracketed = "[";
  bracketed.append(std::to_string(resolution)).append("]");
  replace("[256]", bracketed);
  replace("[256]", bracketed);
  if (!integrator.empty())
    replace("SurfaceIntegrator \"path\" \"integer maxdepth\" [5]", integrator);
  if (!beforeWorldEnd.empty()) replace("WorldEnd", beforeWorldEnd + "WorldEnd");
  return s;
}

std::string exampleSceneText(const std::string& name, const std::string& integrator, int resolution,
                             const std::vector<std::pair<std::string, std::string>>& replace) {
  std::ifstream in(std::string(CANDELA_SOURCE_DIR) + "/scenes/" + name + "/" + name + ".pbrt");
  std::stringstream ss;
  ss << in.rdbuf();
  std::string s = ss.str();
  std::string bracketed = "[";
  bracketed.append(std::to_string(resolution)).append("]");
  std::vector<std::pair<std::string, std::string>> all = {
      {"[256]", bracketed},
      {"[256]", bracketed},
      {"SurfaceIntegrator \"path\" \"integer maxdepth\" [8]", integrator}};
  all.insert(all.end(), replace.begin(), replace.end());
  for (const auto& [from, to] : all) {
    size_t at = s.find(from);
    if (at == std::string::npos) throw std::logic_error(name + ".pbrt has no '" + from + "'");
    s.replace(at, from.size(), to);
  }
  return s;
}

RenderedScene renderSceneText(const std::string& text, const TestRenderOptions& options) {
  return run(text, options.build, &options.render);
}

std::vector<Spectrum> pixelValues(const Film& film) {
  std::vector<Spectrum> values;
  const Bounds2i b = film.pixelBounds();
  for (int y = b.pMin.y; y < b.pMax.y; ++y)
    for (int x = b.pMin.x; x < b.pMax.x; ++x) values.push_back(film.pixelValue(Point2i(x, y)));
  return values;
}

RenderedScene buildSceneText(const std::string& text, const BuildOptions& options) {
  return run(text, options, nullptr);
}

PixelPasses::PixelPasses(RenderJob& job)
    : job_(job), integrator_(dynamic_cast<PixelSampleIntegrator*>(job.integrator.get())) {
  if (!integrator_) throw std::logic_error("PixelPasses: the job's integrator renders no samples");
}

RenderResult PixelPasses::render(const Scene& scene, Film& film,
                                 const RenderOptions& options) const {
  return integrator_->renderSamples({scene, *job_.camera, *job_.sampler}, film, options);
}

RenderPass PixelPasses::pass(const Scene& scene, Film& film) const {
  return [this, &scene, &film](const RenderOptions& o) { return render(scene, film, o); };
}

}  // namespace candela::test
