// SurfaceIntegrator / Integrator "name" -> SurfaceIntegrator.
#include "integrators/ambient_occlusion.h"
#include "integrators/bdpt.h"
#include "integrators/direct_lighting.h"
#include "integrators/path.h"
#include "integrators/whitted.h"
#include "scene/plugin_factories.h"

namespace candela {

namespace {

// "maxdepth" is read only by the integrators that have it, so that anywhere else it is reported
// as unused.
// recursive: the integrator recurses once per level (whitted, directlighting), on a worker
// thread's stack, which two facing mirrors overflow somewhere past 10,000 levels.
int maxDepthParam(const PluginDesc& desc, bool recursive) {
  const ParamSet& p = desc.params;
  int maxDepth = p.getOneInt("maxdepth", 5);
  if (maxDepth < 0) throw SceneError(p.locationOf("maxdepth", desc.loc), "maxdepth must be >= 0");
  constexpr int kMaxRecursion = 1000;
  if (recursive && maxDepth > kMaxRecursion)
    throw SceneError(p.locationOf("maxdepth", desc.loc),
                     std::string("maxdepth must be at most ")
                         .append(std::to_string(kMaxRecursion))
                         .append(" for '")
                         .append(desc.name)
                         .append("', which recurses once per level; got ")
                         .append(std::to_string(maxDepth)));
  return maxDepth;
}

}  // namespace

namespace {

// pbrt-v2/lrt "bidirectional" (maxdepth; the draft's integrator has no parameters of its own) and
// pbrt-v3 "bdpt" (maxdepth, lightsampler, visualizestrategies, visualizeweights).
std::unique_ptr<SurfaceIntegrator> createBdpt(const PluginDesc& desc, const Camera* camera,
                                              const Bounds2i& pixelBounds) {
  const ParamSet& p = desc.params;
  int maxDepth = maxDepthParam(desc, false);
  BdptIntegrator::LightChoice choice = BdptIntegrator::LightChoice::Power;
  BdptIntegrator::Visualize visualize = BdptIntegrator::Visualize::None;
  if (desc.name == "bdpt") {
    // pbrt-v3: the weighted images win when both are asked for.
    if (p.getOneBool("visualizestrategies", false))
      visualize = BdptIntegrator::Visualize::Strategies;
    if (p.getOneBool("visualizeweights", false)) visualize = BdptIntegrator::Visualize::Weights;
    std::string sampler = p.getOneString("lightsampler", "power");
    if (sampler == "uniform")
      choice = BdptIntegrator::LightChoice::Uniform;
    else if (sampler != "power")
      throw SceneError(p.locationOf("lightsampler", desc.loc),
                       std::string("unknown lightsampler '")
                           .append(sampler)
                           .append("' (known: power, uniform)"));
  }
  const CameraImportance* importance = camera ? camera->importance() : nullptr;
  if (!importance)
    throw SceneError(desc.loc, std::string("surface integrator '")
                                   .append(desc.name)
                                   .append("' connects light paths to the camera, which the '")
                                   .append(camera ? camera->kind() : "(none)")
                                   .append("' camera does not support (use 'perspective')"));
  return std::make_unique<BdptIntegrator>(*importance, maxDepth, choice, visualize, pixelBounds);
}

}  // namespace

std::unique_ptr<SurfaceIntegrator> createSurfaceIntegrator(const PluginDesc& desc,
                                                           const Camera* camera,
                                                           const Bounds2i& pixelBounds) {
  const ParamSet& p = desc.params;
  if (desc.name == "bidirectional" || desc.name == "bdpt")
    return createBdpt(desc, camera, pixelBounds);
  if (desc.name == "directlighting") {
    int maxDepth = maxDepthParam(desc, true);
    std::string strategy = p.getOneString("strategy", "all");
    DirectLightingIntegrator::Strategy s;
    if (strategy == "all")
      s = DirectLightingIntegrator::Strategy::All;
    else if (strategy == "one")
      s = DirectLightingIntegrator::Strategy::One;
    else
      throw SceneError(
          p.locationOf("strategy", desc.loc),
          std::string("unknown strategy '").append(strategy).append("' (known: all, one)"));
    return std::make_unique<DirectLightingIntegrator>(s, maxDepth);
  }
  if (desc.name == "path") return std::make_unique<PathIntegrator>(maxDepthParam(desc, false));
  if (desc.name == "whitted") return std::make_unique<WhittedIntegrator>(maxDepthParam(desc, true));
  if (desc.name == "ambientocclusion") {
    // pbrt-v2's defaults: 2048 directions, unbounded probe rays.
    int nSamples = p.getOneInt("nsamples", 2048);
    if (nSamples < 1) throw SceneError(p.locationOf("nsamples", desc.loc), "nsamples must be >= 1");
    Float maxDist = p.getOneFloat("maxdist", kInfinity);
    if (!(maxDist > 0)) throw SceneError(p.locationOf("maxdist", desc.loc), "maxdist must be > 0");
    // pbrt-v3's switch: cosine-weighted directions (default) or pbrt-v2's uniform ones.
    bool cosSample = p.getOneBool("cossample", true);
    return std::make_unique<AmbientOcclusionIntegrator>(nSamples, maxDist, cosSample);
  }
  throwUnknownPlugin(
      desc.loc, "surface integrator", desc.name,
      {"ambientocclusion", "bdpt", "bidirectional", "directlighting", "path", "whitted"});
}

}  // namespace candela
