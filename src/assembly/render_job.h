// Everything one WorldEnd renders, created from a SceneDescription by the factories: only what
// the scene uses is built (DESIGN.md, data flow step 2). The job owns every object; the Scene,
// renderer and integrator hold plain pointers into it.
#pragma once

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "accel/aggregate.h"
#include "accel/scene_geometry.h"
#include "assembly/material_factory.h"
#include "assembly/texture_factory.h"
#include "cameras/camera.h"
#include "core/compatibility.h"
#include "film/film.h"
#include "integrators/integrator.h"
#include "integrators/pixel_sample_integrator.h"
#include "lights/light.h"
#include "materials/material.h"
#include "parser/scene_description.h"
#include "samplers/sampler.h"
#include "scene/scene.h"
#include "shapes/shape.h"
#include "textures/noise.h"
#include "transport/volume_integrator.h"

namespace candela {

class EmbreeDevice;
class MaterialFactory;
class NamedMedia;
struct TriangleMesh;

using WarningSink = std::function<void(const FileLoc&, const std::string&)>;

struct BuildOptions {
  uint64_t seed = 0;
  int sppOverride = 0;                 // 0: the sampler's own count
  std::optional<Bounds2f> cropWindow;  // NDC, overrides the film's
  // --tile: render only tile tileIndex of a grid of tileCount tiles (integrators/tile_grid.h) over
  // the pixels the film would render (its crop window's); tileCount 0 renders them all.
  int tileIndex = 0, tileCount = 0;
  bool quick = false;       // quarter resolution, an eighth of the samples
  std::string accelerator;  // overrides the Accelerator statement ("" = the scene's)
  // Overrides the integrator's "lightsamplestrategy" (path, volpath, bdpt; "" = the scene's).
  std::string lightSampler;
  bool guiding = false;  // turns on the integrator's "guiding" (path)
  // The dialect (--dialect; default: detected) and every pbrt-compatibility switch.
  CompatibilityProfile compatibility;
  unsigned aovs = 0;  // AovFlag bits, added to the Film's "aovs"
  // scene_linear RGB -> working-space RGB for every colour parameter (--colorspace); none =
  // identity.
  std::optional<std::array<Float, 9>> colorMatrix;
  WarningSink warn;           // may be empty
  int nThreads = 0;           // for the integrator's preprocess (0: all cores)
  bool showProgress = false;  // the preprocess's progress on standard error
  // Reads an image texture's file, converted to scene_linear from colorSpace ("" = the default
  // rule: sRGB for integer pixels, linear for float ones). Empty: image textures are an error.
  std::function<ImageBuffer(const std::string& path, const std::string& colorSpace)> loadImage;
};

// What was created, for --stats and for tests that check nothing unneeded was built.
struct BuildStats {
  std::map<std::string, long> shapesByKind;  // "sphere", "triangle", ...
  long triangleMeshes = 0;
  long lights = 0, areaLights = 0;
  long materials = 0;
  long textures = 0;
  long volumeRegions = 0;                     // pbrt-v2 Volume statements
  long namedMedia = 0, mediumInterfaces = 0;  // pbrt-v3 media created, shapes' interfaces
  AggregateStats aggregate;
  std::string report() const;
};

struct RenderJob {
  RenderJob();
  std::unique_ptr<SceneDescription> convertedDescription;  // set when colours were converted
  ~RenderJob();
  RenderJob(RenderJob&&) noexcept;
  RenderJob& operator=(RenderJob&&) noexcept;

  std::unique_ptr<TextureFactory> textures;
  std::unique_ptr<MaterialFactory> materialFactory;  // lives as long as the materials
  std::vector<std::unique_ptr<Material>> materials;
  std::vector<std::unique_ptr<TriangleMesh>> meshes;
  std::vector<std::unique_ptr<Shape>> shapes;
  std::vector<std::unique_ptr<Light>> lights;
  SceneGeometry geometry;                  // the aggregate's primitives and instances
  std::unique_ptr<NamedMedia> namedMedia;  // pbrt-v3's media and interfaces the scene names
  std::unique_ptr<Aggregate> aggregate;
  std::unique_ptr<Scene> scene;
  // pbrt-v2 Volume regions: the medium filling the scene and the integrator that renders it;
  // both null in a scene without regions.
  std::unique_ptr<Medium> volume;
  std::unique_ptr<VolumeIntegrator> volumeIntegrator;
  std::unique_ptr<Film> film;
  // The pixels the whole image has (the film's crop window's): with BuildOptions::tileCount, what
  // the tiles cover together; else the film's own pixel bounds.
  Bounds2i imageRegion;
  // The Film's output parameters ("compression", "half"); command-line flags override them.
  std::string exrCompression = "zip";
  bool exrHalf = false;
  // The Film's "noisethreshold" and "adaptiveminsamples"; --noise-threshold and
  // --adaptive-min-samples override them.
  AdaptiveSampling adaptive;
  std::unique_ptr<Camera> camera;
  std::unique_ptr<Sampler> sampler;
  // What renders the image: a pixel-sample integrator (path, bdpt, ...) or one of the whole
  // image (SPPM, Metropolis).
  std::unique_ptr<Integrator> integrator;
  // Wall time of the integrator's preprocess (photon maps, VPLs) at build: renderJob counts it as
  // render time, so that methods with and without a prepass compare by their whole cost.
  double preprocessSeconds = 0;
  BuildStats stats;
};

// Renders the job with its integrator (Integrator::render), the preprocess counted as render time.
// Throws std::runtime_error for adaptive sampling with an integrator whose pixels do not hold
// all of their light (PixelLight other than OwnSamples).
ProgressiveResult renderJob(RenderJob& job, const ProgressiveOptions& options);

RenderJob buildRenderJob(const SceneDescription& desc, const BuildOptions& options,
                         const EmbreeDevice& device);

}  // namespace candela
