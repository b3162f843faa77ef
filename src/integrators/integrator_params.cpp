// The pixel-sample integrators' create functions (integrator_plugins.cpp's table): each one's
// parameters, defaults and checks.
#include "core/number_file.h"
#include "core/scene_path.h"
#include "integrators/ambient_occlusion.h"
#include "integrators/bdpt.h"
#include "integrators/dipole_subsurface.h"
#include "integrators/direct_lighting.h"
#include "integrators/instant_global_illumination.h"
#include "integrators/integrator_plugins.h"
#include "integrators/irradiance/irradiance_cache_integrator.h"
#include "integrators/path.h"
#include "integrators/photon_map_params.h"
#include "integrators/volpath.h"
#include "integrators/whitted.h"

namespace candela {

namespace {

// "maxdepth" is read only by the integrators that have it, so that anywhere else it is reported
// as unused.
// recursive: the integrator recurses once per level (whitted, directlighting), on a worker
// thread's stack, which two facing mirrors overflow somewhere past 10,000 levels; 1000 is safe.
int maxDepthParam(const IntegratorInputs& desc, bool recursive, const char* name = "maxdepth") {
  return desc.params.getOneInt(
      name, 5, recursive ? ValueRange::within(0, 1000) : ValueRange::atLeast(0), desc.loc);
}

// "irradiancecache" with both dialects' parameters (their mapping: irradiance_cache_settings.h).
IrradianceCacheSettings irradianceCacheParams(const IntegratorInputs& desc) {
  const ParamSet& p = desc.params;
  IrradianceCacheSettings s;
  const FileLoc& at = desc.loc;
  s.maxError = p.getOneFloat("maxerror", s.maxError, ValueRange::nonNegative(), at);  // 0: none
  s.minWeight = p.getOneFloat("minweight", s.minWeight, ValueRange::nonNegative(), at);
  s.minPixelSpacing =
      p.getOneFloat("minpixelspacing", s.minPixelSpacing, ValueRange::nonNegative(), at);
  s.maxPixelSpacing =
      p.getOneFloat("maxpixelspacing", s.maxPixelSpacing, ValueRange::positive(), at);
  if (s.minPixelSpacing > s.maxPixelSpacing)
    throw SceneError(
        p.locationOf(p.find("minpixelspacing") ? "minpixelspacing" : "maxpixelspacing", at),
        "minpixelspacing (" + std::to_string(s.minPixelSpacing) +
            ") must not exceed maxpixelspacing (" + std::to_string(s.maxPixelSpacing) + ")");
  s.maxAngleDifference = p.getOneFloat("maxangledifference", s.maxAngleDifference,
                                       ValueRange::aboveUpTo(0, 90), at);  // degrees
  s.nSamples = p.getOneInt("nsamples", s.nSamples, ValueRange::atLeast(1), at);
  s.nFilter = p.getOneInt("nfilter", s.nFilter, ValueRange::atLeast(0), at);
  s.nFilter = std::min(s.nFilter, s.nSamples - 1);  // the draft's clamp: keep one value
  s.maxSpecularDepth = maxDepthParam(desc, true, "maxspeculardepth");
  s.maxIndirectDepth =
      p.getOneInt("maxindirectdepth", s.maxIndirectDepth, ValueRange::atLeast(0), at);
  return s;
}

}  // namespace

// pbrt-v2's "igi" parameters and defaults (pbrt 2e §15.4).
std::unique_ptr<PixelSampleIntegrator> createIgiIntegrator(const IntegratorInputs& desc) {
  const ParamSet& p = desc.params;
  const FileLoc& at = desc.loc;
  IgiParameters igi;
  igi.pathsPerSet = p.getOneInt("nlights", 64, ValueRange::atLeast(1), at);
  igi.nSets = p.getOneInt("nsets", 4, ValueRange::atLeast(1), at);
  // The VPL sets are numbered with 32-bit indices.
  if (int64_t(igi.pathsPerSet) * igi.nSets > int64_t(1) << 30)
    throw SceneError(p.locationOf("nlights", at), "nlights * nsets must be at most 2^30");
  igi.rrThreshold = p.getOneFloat("rrthreshold", 1e-4f, ValueRange::atLeast(0), at);
  igi.maxDepth = maxDepthParam(desc, true);
  igi.gLimit = p.getOneFloat("glimit", 10, ValueRange::greaterThan(0), at);
  igi.gatherSamples = p.getOneInt("gathersamples", 16, ValueRange::atLeast(0), at);
  return std::make_unique<InstantGlobalIlluminationIntegrator>(igi);
}

namespace {

// A light sample strategy parameter (lightsamplestrategy: uniform, power, spatial or bvh), a
// located SceneError for any other name.
LightSampleStrategy lightStrategyParam(const IntegratorInputs& desc, const char* name,
                                       const char* byDefault) {
  std::string strategy = desc.params.getOneString(
      name, byDefault, {std::begin(kLightSampleStrategyNames), std::end(kLightSampleStrategyNames)},
      desc.loc);
  return *lightSampleStrategyNamed(strategy);
}

// pbrt-v3's "lightsamplestrategy" of path and volpath: in pbrt-v3 scenes that name none,
// "spatial" unless the scene has very many lights (SpatialUnlessMany), else uniform (pbrt-v2's
// choice).
LightSampleStrategy pathLightStrategy(const IntegratorInputs& desc) {
  if (desc.dialect == SceneDialect::PbrtV3 && !desc.params.find("lightsamplestrategy"))
    return LightSampleStrategy::SpatialUnlessMany;
  return lightStrategyParam(desc, "lightsamplestrategy", "uniform");
}

// pbrt-v3's "rrthreshold" of path and volpath (default 1).
Float rrThresholdParam(const IntegratorInputs& desc) {
  return desc.params.getOneFloat("rrthreshold", 1, ValueRange::nonNegative(), desc.loc);
}

// pbrt-v2/lrt "bidirectional" (maxdepth; the draft's integrator has no parameters of its own) and,
// with v3Params, pbrt-v3 "bdpt" (maxdepth, lightsamplestrategy, visualizestrategies,
// visualizeweights).
std::unique_ptr<PixelSampleIntegrator> bdptIntegrator(const IntegratorInputs& desc, bool v3Params) {
  const Camera* camera = desc.camera;
  const Bounds2i& pixelBounds = desc.pixelBounds;
  const ParamSet& p = desc.params;
  int maxDepth = maxDepthParam(desc, false);
  LightSampleStrategy strategy = LightSampleStrategy::Power;
  BdptIntegrator::Visualize visualize = BdptIntegrator::Visualize::None;
  if (v3Params) {
    // pbrt-v3: the weighted images win when both are asked for.
    if (p.getOneBool("visualizestrategies", false))
      visualize = BdptIntegrator::Visualize::Strategies;
    if (p.getOneBool("visualizeweights", false)) visualize = BdptIntegrator::Visualize::Weights;
    // pbrt-v3's name, or "lightsampler", candela's before it.
    const char* name = p.find("lightsamplestrategy") ? "lightsamplestrategy" : "lightsampler";
    strategy = lightStrategyParam(desc, name, "power");
  }
  const CameraImportance* importance = camera ? camera->importance() : nullptr;
  if (!importance)
    throw SceneError(desc.loc, std::string("surface integrator '")
                                   .append(desc.name)
                                   .append("' connects light paths to the camera, which the '")
                                   .append(camera ? camera->kind() : "(none)")
                                   .append("' camera does not support (use 'perspective')"));
  // The camera's position, where "spatial" looks up its distribution: the lens point of the ray
  // through the film's centre.
  CameraSample centre;
  centre.pFilm = Point2f(Float(pixelBounds.pMin.x + pixelBounds.pMax.x) / 2,
                         Float(pixelBounds.pMin.y + pixelBounds.pMax.y) / 2);
  centre.pLens = Point2f(0.5f, 0.5f);
  Ray ray;
  Point3f position(0, 0, 0);
  if (camera->generateRay(centre, &ray) > 0) position = importance->lensPoint(ray);
  return std::make_unique<BdptIntegrator>(*importance, maxDepth, strategy, visualize, pixelBounds,
                                          position);
}

// dipolesubsurface's pointsfile, in pbrt-v2's format: eight numbers per point — position (3),
// normal (3), area, and a ray offset — in world space. Unlike pbrt-v2, which warns and drops
// them, values left over past the last whole point, a zero normal, a negative area or offset, and
// a file without points are errors.
std::vector<SubsurfacePoint> readSubsurfacePointsFile(const std::string& path, const FileLoc& loc) {
  std::vector<double> v;
  try {
    v = readNumberFile(path);
  } catch (const FileError& e) {
    throw SceneError(loc, std::string("dipolesubsurface: cannot read pointsfile: ") + e.what());
  }
  auto fail = [&](const std::string& what) {
    throw SceneError(loc, "dipolesubsurface: pointsfile '" + path + "': " + what);
  };
  if (v.empty()) fail("no points");
  if (v.size() % 8 != 0)
    fail(std::to_string(v.size()) + " values, not a multiple of 8 (x y z nx ny nz area offset)");
  std::vector<SubsurfacePoint> points;
  points.reserve(v.size() / 8);
  for (size_t i = 0; i < v.size(); i += 8) {
    SubsurfacePoint sp;
    sp.p = Point3f(Float(v[i]), Float(v[i + 1]), Float(v[i + 2]));
    Normal3f n = Normal3f(Float(v[i + 3]), Float(v[i + 4]), Float(v[i + 5]));
    Float area = Float(v[i + 6]), offset = Float(v[i + 7]);
    std::string which = "point " + std::to_string(i / 8 + 1) + ": ";
    if (!(n.lengthSquared() > 0)) fail(which + "zero normal");
    if (!(area >= 0)) fail(which + "negative area");
    if (!(offset >= 0)) fail(which + "negative ray offset");
    sp.n = normalize(n);
    sp.area = area;
    sp.pError = Vector3f(offset, offset, offset);
    points.push_back(sp);
  }
  return points;
}

}  // namespace

std::unique_ptr<PixelSampleIntegrator> createBdptIntegrator(const IntegratorInputs& desc) {
  return bdptIntegrator(desc, true);
}

std::unique_ptr<PixelSampleIntegrator> createBidirectionalIntegrator(const IntegratorInputs& desc) {
  return bdptIntegrator(desc, false);
}

// pbrt-v2's "dipolesubsurface" (pbrt 2e §16.5).
std::unique_ptr<PixelSampleIntegrator> createDipoleSubsurfaceIntegrator(
    const IntegratorInputs& desc) {
  const ParamSet& p = desc.params;
  DipoleSubsurfaceSettings s;
  s.maxDepth = maxDepthParam(desc, true);
  s.maxError = p.getOneFloat("maxerror", s.maxError, ValueRange::nonNegative(), desc.loc);
  s.minSampleDistance =
      p.getOneFloat("minsampledistance", s.minSampleDistance, ValueRange::positive(), desc.loc);
  std::string pointsFile = p.getOneString("pointsfile", "");
  if (!pointsFile.empty()) {
    FileLoc loc = p.locationOf("pointsfile", desc.loc);
    s.pointsFile = resolveScenePath(pointsFile, loc.file);
    s.givenPoints = readSubsurfacePointsFile(s.pointsFile, loc);
  }
  return std::make_unique<DipoleSubsurfaceIntegrator>(s);
}

// pbrt-v3's "rrthreshold" and "lightsamplestrategy" (default 1 and "spatial" in pbrt-v3 scenes;
// pbrt-v2's path has neither: every path faces roulette, lights are chosen uniformly, unless the
// scene gives the parameters).
std::unique_ptr<PixelSampleIntegrator> createPathIntegrator(const IntegratorInputs& desc) {
  const ParamSet& p = desc.params;
  const bool v3 = desc.dialect == SceneDialect::PbrtV3;
  PathSettings s;
  s.maxDepth = maxDepthParam(desc, false);
  s.pbrtV3Roulette = v3 || p.find("rrthreshold") != nullptr;
  s.rrThreshold = rrThresholdParam(desc);
  s.lightStrategy = pathLightStrategy(desc);
  s.guiding = p.getOneBool("guiding", false);
  return std::make_unique<PathIntegrator>(s);
}

// pbrt-v3's VolPathIntegrator parameters and defaults.
std::unique_ptr<PixelSampleIntegrator> createVolPathIntegrator(const IntegratorInputs& desc) {
  // One at a time: a call's arguments are read in no set order, and the first bad one is reported.
  int maxDepth = maxDepthParam(desc, false);
  Float rrThreshold = rrThresholdParam(desc);
  LightSampleStrategy strategy = pathLightStrategy(desc);
  bool guiding = desc.params.getOneBool("guiding", false);
  return std::make_unique<VolPathIntegrator>(maxDepth, rrThreshold, strategy, guiding);
}

std::unique_ptr<PixelSampleIntegrator> createDirectLightingIntegrator(
    const IntegratorInputs& desc) {
  int maxDepth = maxDepthParam(desc, true);
  std::string strategy = desc.params.getOneString("strategy", "all", {"all", "one"}, desc.loc);
  DirectLightingIntegrator::Strategy s = strategy == "all"
                                             ? DirectLightingIntegrator::Strategy::All
                                             : DirectLightingIntegrator::Strategy::One;
  return std::make_unique<DirectLightingIntegrator>(s, maxDepth);
}

std::unique_ptr<PixelSampleIntegrator> createWhittedIntegrator(const IntegratorInputs& desc) {
  return std::make_unique<WhittedIntegrator>(maxDepthParam(desc, true));
}

std::unique_ptr<PixelSampleIntegrator> createAmbientOcclusionIntegrator(
    const IntegratorInputs& desc) {
  const ParamSet& p = desc.params;
  // pbrt-v2's defaults: 2048 directions, unbounded probe rays.
  int nSamples = p.getOneInt("nsamples", 2048, ValueRange::atLeast(1), desc.loc);
  Float maxDist = p.getOneFloat("maxdist", kInfinity, ValueRange::greaterThan(0), desc.loc);
  // pbrt-v3's switch: cosine-weighted directions (default) or pbrt-v2's uniform ones.
  bool cosSample = p.getOneBool("cossample", true);
  return std::make_unique<AmbientOcclusionIntegrator>(nSamples, maxDist, cosSample);
}

// pbrt-v3's AOIntegrator: 64 directions, unbounded probes, the unnormalised cosine integral.
std::unique_ptr<PixelSampleIntegrator> createAoIntegrator(const IntegratorInputs& desc) {
  const ParamSet& p = desc.params;
  int nSamples = p.getOneInt("nsamples", 64, ValueRange::atLeast(1), desc.loc);
  bool cosSample = p.getOneBool("cossample", true);
  return std::make_unique<AmbientOcclusionIntegrator>(
      nSamples, kInfinity, cosSample, AmbientOcclusionIntegrator::Estimate::UnoccludedCosine);
}

std::unique_ptr<PixelSampleIntegrator> createIrradianceCacheIntegrator(
    const IntegratorInputs& desc) {
  return std::make_unique<IrradianceCacheIntegrator>(irradianceCacheParams(desc));
}

// pbrt-v2 registers its photon mapper under both names; nothing differs.
std::unique_ptr<PixelSampleIntegrator> createPhotonMapIntegrator(const IntegratorInputs& desc) {
  return std::make_unique<PhotonMapIntegrator>(photonMapSettings(desc.params, desc.loc));
}

}  // namespace candela
