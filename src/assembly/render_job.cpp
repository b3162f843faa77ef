#include "assembly/render_job.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "accel/aggregate_factory.h"
#include "accel/embree/embree_aggregate.h"
#include "assembly/material_factory.h"
#include "assembly/named_media.h"
#include "assembly/plugin_factories.h"
#include "assembly/shape_factory.h"
#include "assembly/volume_factory.h"
#include "integrators/integrator_plugins.h"
#include "integrators/tile_grid.h"
#include "parser/scene_dialect.h"
#include "parser/working_color_space.h"
#include "shapes/triangle_mesh.h"

namespace candela {

RenderJob::RenderJob() = default;
RenderJob::~RenderJob() = default;
RenderJob::RenderJob(RenderJob&&) noexcept = default;
RenderJob& RenderJob::operator=(RenderJob&&) noexcept = default;

std::string BuildStats::report() const {
  std::ostringstream os;
  os << "Scene statistics\n";
  for (const auto& [kind, n] : shapesByKind) os << "  shapes: " << kind << "  " << n << "\n";
  os << "  triangle meshes  " << triangleMeshes << "\n";
  os << "  lights  " << lights << " (area lights " << areaLights << ")\n";
  os << "  materials  " << materials << "\n";
  os << "  textures loaded  " << textures << "\n";
  os << "  volume regions  " << volumeRegions << "\n";
  os << "  named media  " << namedMedia << " (interfaces " << mediumInterfaces << ")\n";
  os << "  aggregate  " << aggregate.name << "\n";
  for (const auto& [what, n] : aggregate.counts) os << "  " << what << "  " << n << "\n";
  return os.str();
}

namespace {

void reportUnused(const PluginDesc& d, const WarningSink& warn) {
  if (!warn) return;
  d.params.forEachUnused([&](const ParamItem& item) {
    warn(item.loc,
         "parameter \"" + item.typeName + " " + item.name + "\" of '" + d.name + "' was not used");
  });
}

// A copy of params with an item of the given type replaced, its value set by setValue.
template <typename SetValue>
ParamSet withItem(const ParamSet& params, ParamType type, const char* typeName,
                  const std::string& name, const FileLoc& loc, SetValue setValue) {
  ParamSet p = params;
  ParamItem item;
  item.type = type;
  item.name = name;
  item.typeName = typeName;
  item.loc = loc;
  setValue(item);
  p.add(item);
  return p;
}

// A copy of params with an integer item replaced (for --quick and --spp).
ParamSet withInt(const ParamSet& params, const std::string& name, int value, const FileLoc& loc) {
  return withItem(params, ParamType::Integer, "integer", name, loc,
                  [&](ParamItem& item) { item.ints = {value}; });
}

// Whether the integrator plug-in of that name has the parameter.
bool integratorHasParam(const std::string& integrator, const char* name) {
  for (const IntegratorPlugin& plugin : integratorPlugins())
    if (plugin.spec.name == integrator)
      for (const ParamSpec& param : plugin.spec.params)
        if (param.name == name) return true;
  return false;
}

// The integrator statement with --light-sampler in place of its lightsamplestrategy, for the
// integrators that read one; a warning for the others.
PluginDesc withLightSampler(const PluginDesc& integrator, const std::string& strategy,
                            const WarningSink& warn) {
  if (strategy.empty()) return integrator;
  if (!integratorHasParam(integrator.name, "lightsamplestrategy")) {
    if (warn)
      warn(integrator.loc,
           "--light-sampler is ignored: integrator '" + integrator.name +
               "' does not choose lights by a strategy (path, volpath and bdpt do)");
    return integrator;
  }
  PluginDesc d = integrator;
  d.params = withItem(integrator.params, ParamType::String, "string", "lightsamplestrategy",
                      FileLoc{"--light-sampler", 0, 0},
                      [&](ParamItem& item) { item.strings = {strategy}; });
  return d;
}

// The integrator statement with --guiding's "bool guiding" true, for the integrators that have
// it; a warning for the others.
PluginDesc withGuiding(const PluginDesc& integrator, bool guiding, const WarningSink& warn) {
  if (!guiding) return integrator;
  if (!integratorHasParam(integrator.name, "guiding")) {
    if (warn)
      warn(integrator.loc, "--guiding is ignored: integrator '" + integrator.name +
                               "' has no path guiding (path and volpath have)");
    return integrator;
  }
  PluginDesc d = integrator;
  d.params = withItem(integrator.params, ParamType::Bool, "bool", "guiding",
                      FileLoc{"--guiding", 0, 0}, [](ParamItem& item) { item.bools = {true}; });
  return d;
}

PluginDesc orDefault(const PluginDesc& d, const std::string& name) {
  if (!d.name.empty()) return d;
  PluginDesc r = d;
  r.name = name;
  return r;
}

// Materials are created once per statement, and only when a shape uses them, by the job's
// MaterialFactory (which also resolves mix's named materials and shares measured tables).
class MaterialCache {
 public:
  MaterialCache(const SceneDescription& desc, RenderJob& job, const WarningSink& warn,
                const CompatibilityProfile& models) {
    auto used = [warn](const PluginDesc& d) { reportUnused(d, warn); };
    job.materialFactory =
        std::make_unique<MaterialFactory>(desc, *job.textures, &job.materials, used, models, warn);
    factory_ = job.materialFactory.get();
  }
  const Material* get(int index) { return factory_->get(index); }

 private:
  MaterialFactory* factory_;
};

// Creates the shapes of sd under objectToWorld and appends their primitives to *out. When
// noAreaLight is set, an area light in effect is ignored with that warning.
// Far from the origin floats are coarse: a shape that spans fewer than 64 float steps (6 bits) at
// its distance renders with visibly wrong surfaces and shading, whatever the spawning does. Said,
// naming the statement, rather than left as a silently wrong image (a unit sphere at 1e7: floats
// there are 1 apart).
void warnAboutLostPrecision(const ShapeDesc& sd, const Bounds3f& world, const WarningSink& warn) {
  if (!warn || world.empty()) return;
  double extent = 0, magnitude = 0;
  for (int a = 0; a < 3; ++a) {
    extent = std::max(extent, double(world.pMax[a]) - double(world.pMin[a]));
    magnitude =
        std::max({magnitude, std::abs(double(world.pMin[a])), std::abs(double(world.pMax[a]))});
  }
  if (!(extent > 0) || !std::isfinite(magnitude)) return;
  const double spacing = magnitude * 0x1p-23;  // float spacing at that magnitude (to a factor 2)
  const double steps = extent / spacing;
  if (steps >= 64) return;
  char message[256];
  std::snprintf(message, sizeof message,
                "shape '%s' (bounds %.3g across) is %.3g from the origin, where floats are %.3g "
                "apart: "
                "only %.3g steps across it (its surface and shading lose that precision; move the "
                "scene nearer the origin)",
                sd.name.c_str(), extent, magnitude, spacing, steps);
  warn(sd.loc, message);
}

// Triangles of zero area (collinear or repeated vertices) or with a NaN or infinite vertex are
// never hit and emit nothing (modelling tools leave them behind; pbrt renders on): a warning
// names the statement and how many, rather than an error or a silent skip.
void warnAboutDegenerateTriangles(const ShapeDesc& sd, const CreatedShapes& created,
                                  const WarningSink& warn) {
  if (!warn || !created.mesh) return;
  long degenerate = 0;
  for (const auto& shape : created.shapes)
    if (const auto* tri = dynamic_cast<const TriangleShape*>(shape.get()))
      degenerate += tri->degenerate();
  if (degenerate == 0) return;
  warn(sd.loc, "shape '" + sd.name + "': " + std::to_string(degenerate) + " of " +
                   std::to_string(created.mesh->triangleCount()) +
                   " triangles have zero area or a non-finite vertex; they are skipped (never "
                   "hit, no light)");
}

void addShape(const ShapeDesc& sd, const Transform& objectToWorld, const char* noAreaLight,
              MaterialCache& materials, RenderJob& job, std::vector<Primitive>* out,
              const BuildOptions& options) {
  const MediumInterface* mediumInterface = job.namedMedia->interfaceOf(sd);
  const WarningSink& warn = options.warn;
  bool allowAreaLight = noAreaLight == nullptr;
  CreatedShapes created = createShapes(sd, objectToWorld, *job.textures, options.compatibility);
  reportUnused(sd, warn);
  warnAboutDegenerateTriangles(sd, created, warn);
  // pbrt 3e cannot sample points on curves either (its Curve::Sample is unimplemented).
  if (sd.name == "curve" && sd.areaLight && allowAreaLight)
    throw SceneError(sd.loc, "curves cannot be area lights (no AreaLightSource on a curve)");
  // Static shapes only: in a prototype (object space) the distance is the instance's to add.
  if (out == &job.geometry.primitives) {
    Bounds3f world;
    for (const auto& shape : created.shapes) world = unionOf(world, shape->worldBound());
    warnAboutLostPrecision(sd, world, warn);
  }
  const Material* material = materials.get(sd.material);
  if (created.mesh) {
    job.meshes.push_back(std::move(created.mesh));
    ++job.stats.triangleMeshes;
  }
  // Room for all of a mesh's triangles at once (keeping geometric growth across shapes): pushed one
  // by one, a 1M-triangle mesh's arrays peaked at 1.5 times their size while they doubled.
  auto room = [n = created.shapes.size()](auto& v) {
    if (v.capacity() < v.size() + n) v.reserve(std::max(v.size() + n, 2 * v.capacity()));
  };
  room(*out);
  room(job.shapes);
  for (auto& shape : created.shapes) {
    const AreaLight* area = nullptr;
    // A shape of zero area emits nothing (its power is L area pi): no light to pick.
    if (sd.areaLight && allowAreaLight && shape->area() > 0) {
      std::unique_ptr<AreaLight> light = createAreaLight(*sd.areaLight, shape.get());
      area = light.get();
      job.lights.push_back(std::move(light));
      ++job.stats.areaLights;
    }
    ++job.stats.shapesByKind[shape->kind()];
    out->push_back(Primitive{shape.get(), material, area, mediumInterface});
    job.shapes.push_back(std::move(shape));
  }
  if (sd.areaLight && allowAreaLight) reportUnused(*sd.areaLight, warn);
  if (sd.areaLight && !allowAreaLight && warn) warn(sd.loc, noAreaLight);
}

// pbrt-v3 media that nothing names, and media the integrator would ignore: never a silent
// difference from what the scene asks for.
void warnAboutNamedMedia(const NamedMedia& media, const PluginDesc& integrator, bool wholeImage,
                         const WarningSink& warn) {
  if (!warn) return;
  std::vector<const MediumDesc*> unused = media.unused();
  for (const MediumDesc* m : unused)
    warn(m->loc,
         "named medium '" + m->mediumName + "' is never used (no MediumInterface names it)");
  for (const MediumDesc& m : media.description().media)
    if (std::find(unused.begin(), unused.end(), &m) == unused.end()) reportUnused(m, warn);
  if (!media.used() || (integrator.name == "volpath" && !wholeImage)) return;
  const MediumDesc& first = *media.firstUsed();
  warn(first.loc, "integrator '" + integrator.name + "' ignores participating media: medium '" +
                      first.mediumName + "' (named by the MediumInterface at " +
                      media.firstReferenceLoc().str() +
                      ") has no effect; use Integrator \"volpath\" to render it");
}

AnimatedTransform animated(const AnimatedTransformDesc& d) {
  return AnimatedTransform(d.start, d.startTime, d.end, d.endTime);
}

// The scene's geometry as SceneGeometry (DESIGN.md: static instances are Embree instances,
// animated ones user geometry): static shapes are world-space primitives; each object
// definition that is used becomes one prototype, created once and shared by all its uses; an
// animated shape is created in its object space as a prototype of its own with one instance
// under its animated transform (pbrt-v3 wraps it in a TransformedPrimitive the same way).
void addGeometry(const SceneDescription& desc, MaterialCache& materials, RenderJob& job,
                 const BuildOptions& options) {
  const WarningSink& warn = options.warn;
  SceneGeometry& geometry = job.geometry;
  for (const ShapeDesc& sd : desc.shapes) {
    if (!sd.objectToWorld.isAnimated()) {
      addShape(sd, sd.objectToWorld.start, nullptr, materials, job, &geometry.primitives, options);
      continue;
    }
    auto proto = std::make_unique<InstancePrototype>();
    proto->name = sd.name;
    addShape(sd, Transform(),
             "area lights on shapes with animated transforms are ignored (as in pbrt)", materials,
             job, &proto->primitives, options);
    geometry.instances.push_back(Instance{proto.get(), animated(sd.objectToWorld)});
    geometry.prototypes.push_back(std::move(proto));
  }
  std::map<std::string, const InstancePrototype*> prototypes;
  for (const InstanceUse& use : desc.instanceUses) {
    auto [it, isNew] = prototypes.try_emplace(use.name, nullptr);
    if (isNew) {
      const InstanceDefinition* def = nullptr;
      for (const auto& d : desc.instanceDefinitions)
        if (d.name == use.name) def = &d;
      if (!def) throw SceneError(use.loc, "unknown object '" + use.name + "'");
      auto proto = std::make_unique<InstancePrototype>();
      proto->name = def->name;
      for (const ShapeDesc& sd : def->shapes) {
        // A prototype is static; an animation inside it would need a second instancing level.
        if (sd.objectToWorld.isAnimated() && warn)
          warn(sd.loc,
               "animated transforms of shapes inside object definitions are not supported; "
               "using the start transform");
        addShape(sd, sd.objectToWorld.start,
                 "area lights inside object instances are ignored (as in pbrt)", materials, job,
                 &proto->primitives, options);
      }
      it->second = proto.get();
      geometry.prototypes.push_back(std::move(proto));
    }
    geometry.instances.push_back(Instance{it->second, animated(use.instanceToWorld)});
  }
}

}  // namespace

RenderJob buildRenderJob(const SceneDescription& sceneDesc, const BuildOptions& options,
                         const EmbreeDevice& device) {
  RenderJob job;
  // Colour parameters converted to the working space once, before anything is created; the job
  // keeps the converted description alive for the factories that refer to it.
  if (options.colorMatrix)
    job.convertedDescription =
        std::make_unique<SceneDescription>(convertColors(sceneDesc, *options.colorMatrix));
  const SceneDescription& desc = job.convertedDescription ? *job.convertedDescription : sceneDesc;
  const WarningSink& warn = options.warn;
  const SceneDialect dialect = options.compatibility.dialect.value_or(detectSceneDialect(desc));
  job.textures = std::make_unique<TextureFactory>(desc.textures, options.loadImage, warn,
                                                  dialect == SceneDialect::PbrtV3
                                                      ? TextureFactory::ImageOrigin::BottomLeft
                                                      : TextureFactory::ImageOrigin::TopLeft,
                                                  options.compatibility.clampedOctaves);

  // pbrt-v2 Volume regions (lrt draft ch. 12): one medium filling the scene and the volume
  // integrator that renders it (pbrt-v2's default: "emission"); neither exists without regions.
  job.volume = createSceneVolume(desc.volumes);
  for (const VolumeDesc& v : desc.volumes) reportUnused(v, warn);
  job.stats.volumeRegions = long(desc.volumes.size());
  if (job.volume) {
    PluginDesc volumeIntegratorDesc = orDefault(desc.volumeIntegrator, "emission");
    job.volumeIntegrator = createVolumeIntegrator(volumeIntegratorDesc);
    reportUnused(volumeIntegratorDesc, warn);
  } else if (!desc.volumeIntegrator.name.empty() && warn) {
    warn(desc.volumeIntegrator.loc, "VolumeIntegrator '" + desc.volumeIntegrator.name +
                                        "' is ignored: the scene has no Volume regions");
  }

  // Film and camera.
  PluginDesc filmDesc = orDefault(desc.film, "image");
  ParamSet filmParams = filmDesc.params;
  if (options.quick) {
    int xres = std::max(1, filmParams.getOneInt("xresolution", 640) / 4);
    int yres = std::max(1, filmParams.getOneInt("yresolution", 480) / 4);
    filmParams = withInt(withInt(filmParams, "xresolution", xres, filmDesc.loc), "yresolution",
                         yres, filmDesc.loc);
  }
  PluginDesc filterDesc = orDefault(desc.filter, "box");
  const FilmFrame frame = filmFrame(filmParams, filmDesc.loc, options.cropWindow);
  job.imageRegion = Film::pixelBoundsOf(frame.resolution, frame.cropWindow);
  std::optional<Bounds2f> crop = options.cropWindow;
  if (options.tileCount > 0) {
    try {
      TileGrid grid(job.imageRegion, options.tileCount);
      crop = cropWindowForPixels(grid.tile(options.tileIndex), frame.resolution);
    } catch (const std::invalid_argument& e) {
      throw SceneError(filmDesc.loc, std::string("--tile ")
                                         .append(std::to_string(options.tileIndex))
                                         .append("/")
                                         .append(std::to_string(options.tileCount))
                                         .append(": ")
                                         .append(e.what()));
    }
  }
  job.film = createFilm(filmDesc.name, filmParams,
                        createFilter(filterDesc.name, filterDesc.params, filterDesc.loc),
                        filmDesc.loc, crop);
  job.film->enableAovs(parseAovList(filmParams.getOneString("aovs", ""),
                                    filmParams.locationOf("aovs", filmDesc.loc)) |
                       options.aovs);
  job.exrCompression = filmParams.getOneString("compression", "zip");
  job.exrHalf = filmParams.getOneBool("half", false);
  // Checked by createFilm.
  job.adaptive.noiseThreshold = filmParams.getOneFloat("noisethreshold", 0);
  job.adaptive.minSamples = filmParams.getOneInt("adaptiveminsamples", 0);
  reportUnused(PluginDesc{filmDesc.name, filmParams, filmDesc.loc}, warn);
  reportUnused(filterDesc, warn);
  CameraDesc camDesc = desc.camera;
  if (camDesc.name.empty()) camDesc.name = "perspective";
  // pbrt-v3's Film "diagonal" (mm, checked by createFilm): the physical film the realistic
  // camera's lens images onto.
  job.camera = createCamera(camDesc.name, camDesc.params, animated(camDesc.cameraToWorld),
                            job.film->fullResolution(), camDesc.loc, job.film->diagonal());
  reportUnused(camDesc, warn);

  // Sampler and integrator, and the counts the scene leaves out, by its dialect: pbrt-v3's default
  // sampler is halton (16 samples), the lrt draft's and pbrt-v2's are stratified.
  const bool v3 = dialect == SceneDialect::PbrtV3;
  const SamplerDefaults samplerDefaults = v3 ? SamplerDefaults::PbrtV3 : SamplerDefaults::PbrtV2;
  PluginDesc samplerDesc = orDefault(desc.sampler, v3 ? "halton" : "stratified");
  int spp = options.sppOverride;
  if (options.quick && spp == 0) {
    // Without a warning sink: the count is the scene's and only the eighth of it is used.
    int full = createSampler(
                   samplerDesc.name, samplerDesc.params, options.seed, 0, samplerDesc.loc,
                   [](const FileLoc&, const std::string&) {}, samplerDefaults)
                   ->samplesPerPixel();
    spp = std::max(1, full / 8);
  }
  // createSampler prints to standard error when given no sink; an empty sink here means quiet.
  SamplerWarning samplerWarn = warn;
  if (!samplerWarn) samplerWarn = [](const FileLoc&, const std::string&) {};
  job.sampler = createSampler(samplerDesc.name, samplerDesc.params, options.seed, spp,
                              samplerDesc.loc, samplerWarn, samplerDefaults);
  reportUnused(samplerDesc, warn);
  PluginDesc integratorDesc =
      withLightSampler(!desc.integrator.name.empty()
                           ? desc.integrator
                           : orDefault(desc.surfaceIntegrator, v3 ? "path" : "directlighting"),
                       options.lightSampler, warn);
  integratorDesc = withGuiding(integratorDesc, options.guiding, warn);
  WholeImageContext irc{job.camera.get(), job.sampler.get(),   options.seed,
                        options.quick,    options.sppOverride, job.film->pixelBounds()};
  job.integrator = createWholeImageIntegrator(integratorDesc, desc.renderer, irc);
  const bool wholeImage = job.integrator != nullptr;
  if (wholeImage) {
    reportUnused(desc.renderer, warn);
    if (job.volume && warn)
      warn(desc.volumes.front().loc,
           "Volume regions are ignored by the '" +
               (desc.renderer.name.empty() ? integratorDesc.name : desc.renderer.name) +
               "' renderer; only pixel-sample integrators render them");
  } else {
    if (!desc.renderer.name.empty() && desc.renderer.name != "sampler" && warn)
      warn(desc.renderer.loc,
           "renderer '" + desc.renderer.name + "' is not available; using the sampler renderer");
    std::unique_ptr<PixelSampleIntegrator> pixels =
        createSurfaceIntegrator(integratorDesc, job.camera.get(), job.film->pixelBounds(), dialect);
    // pbrt-v3's sampler integrators keep camera ray differentials at no less than 1/8, whose
    // texture filter widths then stop shrinking past 64 samples per pixel; its bidirectional
    // integrator, the one that splats light subpaths, scales them by 1/sqrt(spp) alone (pbrt 3e
    // §16.3.1), as do its MLT and SPPM.
    if (v3 && pixels->pixelLight() == PixelLight::OwnSamples)
      pixels->setMinDifferentialScale(Float(0.125));
    const VolumeRegionLight regions = pixels->volumeRegionLight();
    if (job.volume && regions == VolumeRegionLight::CameraRayAndDirect && warn)
      warn(desc.volumes.front().loc,
           "Volume regions attenuate only the camera rays and direct lighting of integrator '" +
               integratorDesc.name +
               "'; its other rays (photons, gather and occlusion rays, light subpaths) cross them "
               "unattenuated "
               "(\"path\" or \"volpath\" carry the volume's full effect)");
    if (regions == VolumeRegionLight::Integrator && job.volumeIntegrator) {
      if (!desc.volumeIntegrator.name.empty() && warn)
        warn(desc.volumeIntegrator.loc, "VolumeIntegrator '" + desc.volumeIntegrator.name +
                                            "' is ignored: '" + integratorDesc.name +
                                            "' carries light through the Volume regions itself");
      job.volumeIntegrator.reset();
    }
    job.integrator = std::move(pixels);
  }
  reportUnused(integratorDesc, warn);

  // Geometry, materials and lights: only what the shapes use.
  MaterialCache materials(desc, job, warn, options.compatibility);
  job.namedMedia = std::make_unique<NamedMedia>(desc);
  addGeometry(desc, materials, job, options);
  SceneMedia sceneMedia;
  for (const LightDesc& ld : desc.lights) {
    job.lights.push_back(createLight(ld, options.loadImage));
    if (const Medium* m = job.namedMedia->get(ld.outsideMedium, ld.mediumLoc))
      sceneMedia.lights.push_back({job.lights.back().get(), m});
    reportUnused(ld, warn);
  }
  job.stats.lights = long(job.lights.size());
  job.stats.materials = long(job.materials.size());
  job.stats.textures = job.textures->texturesCreated();
  job.textures->releaseImages();  // every texture is made; the MIP maps hold the texels

  // The --accel flag wins over the Accelerator statement, whose parameters then do not apply.
  PluginDesc accel = desc.accelerator;
  if (!options.accelerator.empty() && options.accelerator != accel.name)
    accel = PluginDesc{options.accelerator, {}, accel.loc};
  job.aggregate = createAggregate(accel.name, accel.params, job.geometry, device, accel.loc);
  reportUnused(accel, warn);
  job.stats.aggregate = job.aggregate->stats();
  std::vector<const Light*> lights;
  for (const auto& l : job.lights) lights.push_back(l.get());
  job.scene = std::make_unique<Scene>(job.aggregate.get(), std::move(lights), job.volume.get());
  sceneMedia.camera = job.namedMedia->get(desc.camera.medium, desc.camera.mediumLoc);
  sceneMedia.present = job.namedMedia->used();
  job.stats.namedMedia = job.namedMedia->createdCount();
  job.stats.mediumInterfaces = job.namedMedia->interfaceCount();
  warnAboutNamedMedia(*job.namedMedia, integratorDesc, wholeImage, warn);
  job.scene->setMedia(std::move(sceneMedia));
  job.scene->setNeedsRayDifferentials(job.textures->texturesCreated() > 0);
  for (const auto& l : job.lights) l->preprocess(job.scene->worldBound());
  if (warn && job.camera->clipsAway(job.scene->worldBound()))
    warn(camDesc.loc,
         "the camera's clipping range (\"hither\", \"yon\") leaves out every object: "
         "the image can show only lights at infinity");
  PreprocessOptions pre;
  pre.seed = options.seed;
  pre.nThreads = options.nThreads;
  pre.showProgress = options.showProgress;
  pre.quick = options.quick;
  pre.shutterOpen = job.camera->shutterOpen();
  pre.shutterClose = job.camera->shutterClose();
  pre.sceneHasSpecular = false;
  for (const auto& m : job.materials) pre.sceneHasSpecular |= m->maybeSpecular();
  pre.sceneHasSubsurface = false;
  for (const auto& m : job.materials) pre.sceneHasSubsurface |= m->subsurface() != nullptr;
  if (options.warn)
    pre.warn = [warn = options.warn, loc = integratorDesc.loc](const std::string& message) {
      warn(loc, message);
    };
  auto start = std::chrono::steady_clock::now();
  job.integrator->preprocess(*job.scene, pre);
  job.preprocessSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return job;
}

ProgressiveResult renderJob(RenderJob& job, const ProgressiveOptions& options) {
  // Adaptive sampling judges a pixel's noise from its own samples; splatted light and whole-image
  // renderers' pixels are not in them (and those integrators take no adaptive passes).
  if (options.adaptive.enabled() && job.integrator->pixelLight() != PixelLight::OwnSamples)
    throw std::runtime_error(
        "adaptive sampling (--noise-threshold or the Film's \"noisethreshold\") judges each "
        "pixel's noise from its own samples, which this scene's integrator does not keep (its "
        "light is splatted or gathered from photons)");
  // The passes' clock starts after the preprocess; reports and the budget count it too.
  ProgressiveOptions po = options;
  po.timeBudget = std::max(0.0, options.timeBudget - job.preprocessSeconds);
  if (options.timeBudget > 0 && po.timeBudget == 0) po.timeBudget = 1e-9;
  if (options.afterPass)
    po.afterPass = [&](const PassReport& pass) {
      PassReport withPrepass = pass;
      withPrepass.seconds += job.preprocessSeconds;
      withPrepass.total.seconds += job.preprocessSeconds;
      return options.afterPass(withPrepass);
    };
  RenderInputs in{*job.scene, *job.camera, *job.sampler, job.volumeIntegrator.get()};
  ProgressiveResult result = job.integrator->render(in, *job.film, po);
  result.total.seconds += job.preprocessSeconds;
  return result;
}

}  // namespace candela
