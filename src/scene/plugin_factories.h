// Name -> object for materials, lights and integrators. Unknown names are errors that list the
// names that exist.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "cameras/camera.h"
#include "integrators/integrator.h"
#include "lights/light.h"
#include "materials/material.h"
#include "scene/scene_description.h"
#include "scene/texture_factory.h"

namespace candela {

[[noreturn]] void throwUnknownPlugin(const FileLoc& loc, const std::string& kind,
                                     const std::string& name,
                                     const std::vector<std::string>& known);

// The material of shapes that name none (pbrt: matte with Kd 0.5).
std::unique_ptr<Material> createDefaultMaterial(TextureFactory& textures);

// Light maps ("mapname") are read through loadImage; without one they are an error.
std::unique_ptr<Light> createLight(const LightDesc& desc,
                                   const TextureFactory::ImageLoader& loadImage = {});
std::unique_ptr<AreaLight> createAreaLight(const PluginDesc& desc, const Shape* shape);

// camera: the scene's, for integrators that connect light paths to it ("bidirectional"/"bdpt");
// such an integrator with a camera that has no importance is a SceneError naming the camera.
// pixelBounds: the film's, for images an integrator makes besides it.
std::unique_ptr<SurfaceIntegrator> createSurfaceIntegrator(const PluginDesc& desc,
                                                           const Camera* camera = nullptr,
                                                           const Bounds2i& pixelBounds = {});

}  // namespace candela
