#include "integrators/metropolis/metropolis_integrator.h"

#include <sstream>

#include "accel/embree/embree_device.h"
#include "cameras/camera.h"
#include "film/film.h"
#include "integrators/direct_lighting.h"
#include "integrators/pixel_sample_integrator.h"

namespace candela {

namespace {

// The chains only splat, which gives the film no alpha: one camera ray through each pixel's
// centre says whether the pixel sees a surface (alpha 1, as the sampler renderer's integrators
// report it) or nothing. Its radiance sample is 0, so the pixel's value stays the splats'.
RayStats coverageAlpha(const Scene& scene, const Camera& camera, Film& film) {
  enableFlushToZero();
  RayStats rays;
  const Bounds2i b = film.pixelBounds();
  for (int y = b.pMin.y; y < b.pMax.y; ++y)
    for (int x = b.pMin.x; x < b.pMax.x; ++x) {
      CameraSample cs;
      cs.pFilm = Point2f(Float(x) + 0.5f, Float(y) + 0.5f);
      cs.pLens = Point2f(0.5f, 0.5f);
      cs.time = 0.5f;
      RayDifferential ray;
      Float alpha = 0;
      if (camera.generateRayDifferential(cs, &ray) > 0) {
        SurfaceInteraction isect;
        ++rays.cameraRays;
        if (scene.intersect(ray, &isect, rays)) alpha = 1;
      }
      film.addSample(Point2i(x, y), Spectrum(0), alpha, 1);
    }
  return rays;
}

}  // namespace

ProgressiveResult MetropolisIntegrator::render(const RenderInputs& in, Film& film,
                                               const ProgressiveOptions& options) {
  const Scene& scene = in.scene;
  const Camera& camera = in.camera;
  // The chains' paths: bdpt's subpaths and connections, its light choice by power.
  BdptIntegrator paths(importance_, settings_.maxDepth, LightSampleStrategy::Power);
  paths.preprocess(scene, PreprocessOptions{});
  ProgressiveResult result;
  if (directSamples_ > 0) {
    // pbrt 2e §15.7: the direct lighting, which the chains leave out, by the sampler renderer
    // with a low-discrepancy sampler of directSamples per pixel (rounded up to a power of two,
    // as that sampler needs); its maxdepth bounds the specular bounces before the surface that
    // is lit as the chains' maxdepth bounds the path.
    DirectLightingIntegrator direct(DirectLightingIntegrator::Strategy::All, settings_.maxDepth);
    std::unique_ptr<Sampler> sampler =
        createSampler("lowdiscrepancy", ParamSet(), seed_, directSamples_, FileLoc{},
                      [](const FileLoc&, const std::string&) {});
    result.total = direct.renderSamples({scene, camera, *sampler}, film, options.render);
  } else {
    result.total.rays = coverageAlpha(scene, camera, film);
  }
  MetropolisStats stats;
  RenderResult chains =
      runMetropolisChains(settings_, paths, scene, camera, film, seed_, options.render, &stats);
  result.total.seconds += chains.seconds;
  result.total.samples += chains.samples;
  result.total.rays += chains.rays;
  result.total.nonFiniteSamples += chains.nonFiniteSamples;
  result.spp = int(std::min<int64_t>(settings_.mutationsPerPixel, INT32_MAX));
  result.passes = 1;
  std::ostringstream os;
  os << "Metropolis\n  b (mean luminance over the image)  " << stats.b << "\n  proposals  "
     << stats.proposals << "\n  accepted  " << stats.accepted;
  if (stats.proposals)
    os << " (" << 100.0 * double(stats.accepted) / double(stats.proposals) << "%)";
  os << "\n";
  if (settings_.maxConsecutiveRejects > 0)
    os << "  forced accepts  " << stats.forcedAccepts << "\n";
  report_ = os.str();
  if (options.afterPass) {
    PassReport pass;
    pass.pass = 0;
    pass.spp = result.spp;
    pass.seconds = result.total.seconds;
    pass.total = result.total;
    options.afterPass(pass);
  }
  return result;
}

}  // namespace candela
