// Name -> object for materials, lights and integrators, through their kinds' tables
// (assembly/plugin_registry.h lists them); unknown names are errors that list the table.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "assembly/texture_factory.h"
#include "cameras/camera.h"
#include "integrators/integrator.h"
#include "integrators/pixel_sample_integrator.h"
#include "lights/light.h"
#include "materials/material.h"
#include "parser/scene_description.h"
#include "parser/scene_dialect.h"
#include "samplers/sampler.h"

namespace candela {

// The material of shapes that name none (pbrt: matte with Kd 0.5).
std::unique_ptr<Material> createDefaultMaterial(TextureFactory& textures);

// Light maps ("mapname") are read through loadImage; without one they are an error.
std::unique_ptr<Light> createLight(const LightDesc& desc, const ImageLoader& loadImage = {});
std::unique_ptr<AreaLight> createAreaLight(const PluginDesc& desc, const Shape* shape);

// camera: the scene's, for integrators that connect light paths to it ("bidirectional"/"bdpt");
// such an integrator with a camera that has no importance is a SceneError naming the camera.
// pixelBounds: the film's, for images an integrator makes besides it. dialect: the scene's, for
// the defaults of parameters whose pbrt-v3 default differs from pbrt-v2's behaviour.
std::unique_ptr<PixelSampleIntegrator> createSurfaceIntegrator(
    const PluginDesc& desc, const Camera* camera = nullptr, const Bounds2i& pixelBounds = {},
    SceneDialect dialect = SceneDialect::PbrtV2);

// What a whole-image integrator may take from the build.
struct WholeImageContext {
  const Camera* camera = nullptr;
  const Sampler* sampler = nullptr;  // its samples per pixel (after --spp and --quick)
  uint64_t seed = 0;
  bool quick = false;
  int sppOverride = 0;   // --spp (0: none), for integrators whose sample count is a parameter
  Bounds2i pixelBounds;  // the film's (crop window applied)
};

// The whole-image integrator that an Integrator statement (pbrt-v3: "sppm", "mlt") or a Renderer
// statement (pbrt-v2: "metropolis") selects; null when the scene renders with the pixel-sample
// integrator of its SurfaceIntegrator or Integrator statement. renderer.name is empty when the
// scene has no Renderer statement. Bad parameters are SceneErrors at their location.
std::unique_ptr<Integrator> createWholeImageIntegrator(const PluginDesc& integrator,
                                                       const PluginDesc& renderer,
                                                       const WholeImageContext& context);

}  // namespace candela
