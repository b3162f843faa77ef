// Writes a rendered frame: the scene-linear EXR (atomically) with its metadata, then the preview.
#pragma once

#include <memory>

#include "app/cli_options.h"
#include "film/film.h"
#include "film/output/image_output.h"
#include "renderers/sampler_renderer.h"
#include "scene/scene_description.h"

namespace candela {

class ColorManagement;

class FrameWriter {
 public:
  // Loads the OCIO config up front, so a bad config fails before any rendering.
  explicit FrameWriter(const CliOptions& cli);
  ~FrameWriter();
  // extra: metadata of the caller's to add (stop conditions, error).
  void write(const Film& film, const SceneDescription& desc, int spp, const RenderResult& result,
             int frameIndex, const ImageMetadata& extra, ExrOptions exr) const;

 private:
  const CliOptions& cli_;
  std::unique_ptr<ColorManagement> colorManagement_;
};

}  // namespace candela
