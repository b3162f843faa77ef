// Writes a rendered frame: the scene-linear EXR with its metadata, then the preview. Every file is
// first written under a hidden name beside its target and renamed only by commit(), after the last
// frame: a failure anywhere (a later frame's error, an interrupt) leaves no output, old files
// untouched, and no temporary file (the destructor removes what was not committed).
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/cli_options.h"
#include "app/staged_files.h"
#include "film/film.h"
#include "film/output/image_output.h"
#include "integrators/integrator.h"
#include "integrators/pixel_sample_integrator.h"
#include "parser/scene_description.h"

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
  // The files a frame will write (its EXR, and its preview unless 'none'), checked before any
  // rendering: each directory must exist, the preview's format must be known and the image
  // plug-in that writes it loadable, and none may be a file the render reads (`inputs`: scene
  // files, textures, the reference). A FileError names the path.
  void checkOutputs(const std::string& filmFilename, int frameIndex,
                    const std::vector<std::string>& inputs) const;
  // extra: metadata of the caller's to add (stop conditions, error).
  void write(const Film& film, const SceneDescription& desc, int spp, const RenderResult& result,
             int frameIndex, const ImageMetadata& extra, ExrOptions exr);
  // An integrator's extra images (bdpt's per-strategy ones), each as an EXR under its own name in
  // the directory of the frame's EXR.
  void writeBeside(const Film& film, int frameIndex, const std::vector<NamedImage>& images,
                   ExrOptions exr);
  // Renames every staged file to its target, and says so unless quiet.
  void commit();

 private:
  const CliOptions& cli_;
  std::unique_ptr<ColorManagement> colorManagement_;
  std::string sceneLinear_, workingSpace_;  // canonical names
  StagedFiles staged_;
  // A hidden name beside target, with its extension (which picks the image format).
  std::string stage(const std::string& target);
  // warnAt: where to say that a non-EXR name was changed (null: say nothing).
  std::string exrPathOf(const std::string& filmFilename, int frameIndex,
                        const FileLoc* warnAt) const;
  std::string previewPathOf(const std::string& exrPath, int frameIndex) const;
};

}  // namespace candela
