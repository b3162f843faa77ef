// "bidirectional" (pbrt-v2/lrt) and "bdpt" (pbrt-v3): bidirectional path tracing (Veach's thesis
// ch. 10; pbrt 3e §16.3). Each camera sample traces a camera subpath and a light subpath and
// connects every prefix pair (s light vertices, t camera vertices): s = 0 is the camera path
// hitting an emitter, s = 1 a fresh light sample (next-event estimation), t = 1 a light-path
// vertex connected to a fresh lens point and splatted to the film where it lands. Every
// strategy's contribution is weighted by the power heuristic over all strategies that could have
// made the same path. maxdepth bounds the path's scattering events (s + t - 2).
#pragma once

#include <memory>
#include <vector>

#include "cameras/camera.h"
#include "core/sampling.h"
#include "filters/filter.h"
#include "integrators/pixel_sample_integrator.h"
#include "lights/light_sampler.h"
#include "transport/bdpt_vertex.h"

namespace candela {

class BdptIntegrator : public PixelSampleIntegrator {
 public:
  // pbrt-v3's visualizestrategies (each strategy's own estimate, unweighted) and visualizeweights
  // (its MIS-weighted share): one image per (s, t), bdpt_dDD_sSS_tTT.exr.
  enum class Visualize { None, Strategies, Weights };
  // pixelBounds: the film's, for the visualisation images.
  // lightStrategy: how the light a light subpath starts from is chosen (pbrt-v3's
  // lightsamplestrategy, "power" by default); "spatial" takes the distribution of the voxel that
  // holds lightReference (the camera's position: pbrt-v3 looks it up at each sample's camera
  // vertex, the same voxel but for lenses wider than one); "bvh" chooses the light subpath's light
  // by power and the light a camera vertex connects to (s = 1) by the light tree at that vertex
  // (the MIS weights keep the subpath's choice: any one density in them for every strategy makes
  // them sum to one, and each strategy divides by the density it sampled with).
  BdptIntegrator(const CameraImportance& camera, int maxDepth, LightSampleStrategy lightStrategy,
                 Visualize visualize = Visualize::None, const Bounds2i& pixelBounds = {},
                 const Point3f& lightReference = Point3f(0, 0, 0));
  ~BdptIntegrator() override;
  void preprocess(const Scene& scene, const PreprocessOptions&) override;
  PixelLight pixelLight() const override { return PixelLight::Splatted; }
  std::vector<NamedImage> extraImages(const Film& film) const override;
  Spectrum Li(const RayDifferential& ray, const Scene& scene, IntegratorContext& ctx,
              Float* alpha) const override;

  // For Metropolis light transport over these paths (pbrt 3e §16.4.4): the subpaths, the
  // connection's fresh samples, each from its own sampler, so that a change in one subpath's
  // length does not shift the numbers the others read.
  struct PathSamplers {
    Sampler& camera;
    Sampler& light;
    Sampler& connection;
  };
  // How the one strategy of a fixed-length path counts: Mis, as bdpt weighs it against all the
  // strategies; Unidirectional, a path tracer's rule (pbrt 2e §15.7's unidirectional paths): at
  // every depth the light sample (s = 1) and, where that cannot make the path (the emitter seen
  // directly or after a specular bounce), the emitter hit (s = 0), each with weight 1.
  enum class Weighting { Mis, Unidirectional };
  // The contribution of the paths of `depth` scattering events that strategy (s light vertices)
  // makes from the camera ray `ray`: Mis uses strategy s alone; Unidirectional ignores s and adds
  // its two strategies. Zero when a subpath ends early. When it lands elsewhere than the ray's
  // own pixel (t = 1), *pRaster is set and *elsewhere true. excludeDirect leaves out what a
  // direct-lighting integrator renders (pbrt 2e §15.7's separate direct lighting): emitters
  // seen directly or through specular bounces only (fewer than maxdepth of them), and light
  // reflected once at the first surface such a chain meets (directlighting with this maxdepth).
  Spectrum fixedLengthContribution(const RayDifferential& ray, int depth, int s,
                                   Weighting weighting, bool excludeDirect, const Scene& scene,
                                   const PathSamplers& samplers, MemoryArena& arena,
                                   RayStats& stats, Point2f* pRaster, bool* elsewhere) const;

 private:
  // Subpaths: vertex 0 is the camera (light), then the surfaces the walk scattered at. Return the
  // number of vertices.
  // maxVertices < 0: the most maxdepth allows.
  int cameraSubpath(const RayDifferential& ray, const Scene& scene, IntegratorContext& ctx,
                    PathVertex* path, int maxVertices = -1) const;
  int lightSubpath(const Scene& scene, IntegratorContext& ctx, Float time, PathVertex* path,
                   int maxVertices = -1) const;
  int randomWalk(RayDifferential ray, Spectrum beta, Float pdfDir, bool fromCamera,
                 const Scene& scene, IntegratorContext& ctx, PathVertex* path,
                 int maxVertices) const;
  // The (s, t) strategy's contribution, MIS weight included; for t = 1, *pRaster is where it lands.
  Spectrum connect(const Scene& scene, PathVertex* light, PathVertex* camera, int s, int t,
                   IntegratorContext& ctx, Point2f* pRaster, Float* weight) const;
  // The visualisation buffer of strategy (s, t): depth d = s + t - 2 has d + 2 strategies.
  static int strategyIndex(int s, int t) {
    int d = s + t - 2;
    return d * (d + 3) / 2 + s;
  }
  Float misWeight(const PathVertex* light, const PathVertex* camera, const PathVertex& sampled,
                  int s, int t) const;

  // f at v from the direction of `prev` toward `next`; light-side vertices (importance transport)
  // get the shading-normal correction (pbrt 3e §16.1.3).
  Spectrum f(const PathVertex& v, const PathVertex& prev, const PathVertex& next,
             bool importance) const;
  // Area density at `next` of the walk continuing from v, which it reached from `prev` (prev may
  // be null at subpath starts).
  Float pdf(const PathVertex& v, const PathVertex* prev, const PathVertex& next) const;
  // Area density at `next` of a light path starting at light vertex v toward it.
  Float pdfLight(const PathVertex& v, const PathVertex& next) const;
  // Density of choosing light vertex v as a light path's origin (area, or solid angle from `next`
  // for points at infinity).
  Float pdfLightOrigin(const PathVertex& v, const PathVertex& next) const;
  // Emitted radiance at v toward `toward` (v an emitter or an environment vertex).
  Spectrum Le(const PathVertex& v, const PathVertex& toward) const;
  Float lightPdf(const Light* light) const;
  // The direction density of all infinite lights together, toward w (toward the sky).
  Float infiniteLightDensity(const Vector3f& w) const;

  const CameraImportance& camera_;
  int maxDepth_;
  LightSampleStrategy lightStrategy_;
  Point3f lightReference_;
  std::vector<const Light*> lights_;
  std::unique_ptr<LightSampler> lightSampler_;
  std::unique_ptr<LightSampler> vertexLightSampler_;  // "bvh": the s = 1 choice; else null
  Point3f sceneCenter_{0, 0, 0};
  Float sceneRadius_ = 0;
  Visualize visualize_;
  std::unique_ptr<Filter> pixelBox_;  // each visualised contribution lands in one pixel
  std::vector<std::unique_ptr<SplatBuffer>> strategyImages_;
};

}  // namespace candela
