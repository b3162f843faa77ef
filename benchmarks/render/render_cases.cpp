#include "render_cases.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "parser/parser.h"
#include "parser/scene_builder.h"

namespace candela::bench {

std::vector<RenderCase> standardCases(const std::string& sourceDir) {
  const std::string cornell = sourceDir + "/scenes/cornell-box/cornell-box.pbrt";
  auto cornellWith = [](const std::string& sampler) {
    return "Sampler \"" + sampler +
           "\" \"integer pixelsamples\" [64]\n"
           "PixelFilter \"box\"\n"
           "SurfaceIntegrator \"path\" \"integer maxdepth\" [8]\n";
  };
  return {{"cornell-halton", cornell, cornellWith("halton")},
          {"cornell-random", cornell, cornellWith("random")},
          {"box-sphere", sourceDir + "/benchmarks/render/scenes/box-sphere.pbrt", ""}};
}

std::unique_ptr<RenderJob> buildCase(const RenderCase& c, uint64_t seed,
                                     const EmbreeDevice& device) {
  std::ifstream in(c.scene);
  if (!in) throw std::runtime_error(c.scene + ": cannot read");
  std::stringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  if (!c.overrides.empty()) {
    size_t at = s.find("\nWorldBegin");
    if (at == std::string::npos) throw std::runtime_error(c.scene + ": no WorldBegin line");
    s.insert(at + 1, c.overrides);
  }
  std::unique_ptr<RenderJob> job;
  SceneBuilder builder(
      [&](SceneDescription&& desc) {
        if (job) return;  // the first frame only
        BuildOptions options;
        options.seed = seed;
        job = std::make_unique<RenderJob>(buildRenderJob(desc, options, device));
      },
      {});
  parseString(s, c.scene, builder);
  builder.endOfInput(FileLoc{c.scene, 0, 0});
  if (!job) throw std::runtime_error(c.scene + ": no WorldEnd");
  return job;
}

}  // namespace candela::bench
