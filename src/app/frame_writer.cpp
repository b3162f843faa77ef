#include "app/frame_writer.h"

#include <cstdio>
#include <filesystem>

#include "app/render_piece.h"
#include "core/error.h"
#include "film/film_sums.h"
#include "film/output/image_output.h"
#include "film/output/image_plugin.h"
#include "film/tonemap/tone_map.h"

namespace candela {

namespace fs = std::filesystem;

FrameWriter::FrameWriter(const CliOptions& cli)
    : cli_(cli), colorManagement_(std::make_unique<ColorManagement>(cli.ocioConfig)) {
  sceneLinear_ = colorManagement_->sceneLinearName();
  workingSpace_ =
      cli.colorSpace.empty() ? sceneLinear_ : colorManagement_->canonicalName(cli.colorSpace);
}

std::optional<std::array<Float, 9>> FrameWriter::workingSpaceMatrix() const {
  if (workingSpace_ == sceneLinear_) return std::nullopt;
  // A linear space to a linear space is a 3x3 matrix: its columns are the images of the
  // scene-linear primaries.
  ImageBuffer basis(3, 1, {"R", "G", "B"});
  for (int i = 0; i < 3; ++i) basis.at(i, 0, i) = 1;
  colorManagement_->convert(basis, sceneLinear_, workingSpace_);
  std::array<Float, 9> m;
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col) m[3 * row + col] = basis.at(col, 0, row);
  return m;
}

FrameWriter::~FrameWriter() = default;

namespace {
std::string joinedSceneNames(const CliOptions& cli) {
  std::string s;
  for (const auto& f : cli.sceneFiles) s += (s.empty() ? "" : " ") + f;
  return s;
}
}  // namespace

std::string FrameWriter::exrPathOf(const std::string& filmFilename, int frameIndex,
                                   const FileLoc* warnAt) const {
  fs::path exrPath = cli_.outfile.empty() ? fs::path(filmFilename) : fs::path(cli_.outfile);
  if (exrPath.extension() != ".exr") {
    fs::path original = exrPath;
    exrPath.replace_extension(".exr");
    if (warnAt && !cli_.quiet)
      std::fprintf(stderr,
                   "%s: warning: output is scene-linear OpenEXR; writing %s instead of %s\n",
                   warnAt->str().c_str(), exrPath.string().c_str(), original.string().c_str());
  }
  return framePath(exrPath.string(), frameIndex);
}

std::string FrameWriter::previewPathOf(const std::string& exrPath, int frameIndex) const {
  if (cli_.preview == "none") return "";
  return (cli_.preview.empty() ? fs::path(exrPath).replace_extension(".png")
                               : fs::path(framePath(cli_.preview, frameIndex)))
      .string();
}

void FrameWriter::checkOutputs(const std::string& filmFilename, int frameIndex,
                               const std::vector<std::string>& inputs) const {
  const std::string exrPath = exrPathOf(filmFilename, frameIndex, nullptr);
  std::vector<std::string> outputs = {exrPath};
  if (std::string preview = previewPathOf(exrPath, frameIndex); !preview.empty()) {
    previewFormat(preview);
    imagePlugin();  // the preview's writer: a missing plug-in fails here, before the render
    outputs.push_back(preview);
  }
  for (const std::string& out : outputs) {
    checkImagePath(out);
    std::error_code ec;
    for (const std::string& in : inputs)
      if (fs::equivalent(fs::path(out), fs::path(in), ec))
        throw FileError(out, "refusing to overwrite '" + in + "', which the render reads");
  }
}

std::string FrameWriter::stage(const std::string& target) { return staged_.stage(target); }

void FrameWriter::commit() { staged_.commit(cli_.quiet); }

void FrameWriter::write(const Film& film, const SceneDescription& desc, int spp,
                        const RenderResult& result, int frameIndex, const ImageMetadata& extra,
                        ExrOptions exr) {
  const std::string exrPath = exrPathOf(film.filename(), frameIndex, &desc.film.loc);

  ImageBuffer image = film.image();
  if (cli_.sampleRange) appendFilmSums(film, image);
  ImageMetadata meta;
  addRenderMetadata(joinedSceneNames(cli_), spp, std::to_string(cli_.seed), result.seconds,
                    result.rays.intersectionRays + result.rays.shadowRays, &meta);
  meta.strings.insert(meta.strings.end(), extra.strings.begin(), extra.strings.end());
  meta.floats.insert(meta.floats.end(), extra.floats.begin(), extra.floats.end());
  meta.ints.insert(meta.ints.end(), extra.ints.begin(), extra.ints.end());

  exr.colorSpace = workingSpace_;
  // Resolved through the config, so a custom config's scene-linear space still gets its primaries.
  exr.chromaticities = colorManagement_->chromaticities(exr.colorSpace);
  writeExr(stage(exrPath), image, meta, exr);

  const std::string previewPath = previewPathOf(exrPath, frameIndex);
  if (previewPath.empty()) return;
  if (workingSpace_ != sceneLinear_) colorManagement_->convert(image, workingSpace_, sceneLinear_);
  // lrt's tone maps act on the preview only; the EXR above keeps the scene-linear data.
  const std::string toneMap = cli_.toneMap.empty() ? desc.toneMap.name : cli_.toneMap;
  if (!toneMap.empty()) applyToneMap(image, toneMap, desc.toneMap.params, desc.toneMap.loc);
  writePreview(stage(previewPath), image, *colorManagement_, cli_.display, cli_.view);
}

void FrameWriter::writeBeside(const Film& film, int frameIndex,
                              const std::vector<NamedImage>& images, ExrOptions exr) {
  fs::path dir = fs::path(exrPathOf(film.filename(), frameIndex, nullptr)).parent_path();
  exr.colorSpace = workingSpace_;
  exr.chromaticities = colorManagement_->chromaticities(exr.colorSpace);
  ImageMetadata meta;
  meta.strings.push_back({"Software", std::string("candela ") + CANDELA_VERSION});
  for (const NamedImage& named : images) {
    writeExr(stage((dir / named.name).string()), named.image, meta, exr);
  }
}

}  // namespace candela
