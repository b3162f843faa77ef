// Writes a rendered frame: the scene-linear EXR (atomically) with its metadata, then the preview.
#pragma once

#include <array>
#include <memory>
#include <optional>

#include "app/cli_options.h"
#include "film/film.h"
#include "film/output/image_output.h"
#include "integrators/integrator.h"
#include "renderers/sampler_renderer.h"
#include "scene/scene_description.h"

namespace candela {

class ColorManagement;

class FrameWriter {
 public:
  // Loads the OCIO config up front, so a bad config fails before any rendering.
  explicit FrameWriter(const CliOptions& cli);
  ~FrameWriter();
  // scene_linear -> working space, when --colorspace names another space.
  std::optional<std::array<Float, 9>> workingSpaceMatrix() const;
  // The OCIO config, and the canonical name of the space colours are rendered in (image textures
  // are converted to it on load).
  const ColorManagement& colorManagement() const { return *colorManagement_; }
  const std::string& workingSpace() const { return workingSpace_; }
  // extra: metadata of the caller's to add (stop conditions, error).
  void write(const Film& film, const SceneDescription& desc, int spp, const RenderResult& result,
             int frameIndex, const ImageMetadata& extra, ExrOptions exr) const;
  // An integrator's extra images (bdpt's per-strategy ones), each as an EXR under its own name in
  // the directory of the frame's EXR.
  void writeBeside(const Film& film, int frameIndex, const std::vector<NamedImage>& images,
                   ExrOptions exr) const;

 private:
  const CliOptions& cli_;
  std::unique_ptr<ColorManagement> colorManagement_;
  std::string sceneLinear_, workingSpace_;  // canonical names
};

}  // namespace candela
