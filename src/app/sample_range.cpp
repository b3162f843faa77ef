#include "app/sample_range.h"

#include "core/error.h"
#include "film/aov.h"

namespace candela {

void checkSampleRange(const RenderJob& job, const IndexRange& range) {
  auto refuse = [&](const std::string& why) {
    return SceneError(FileLoc{"--sample-range " + range.str(), 0, 0}, why);
  };
  const PixelLight pixelLight = job.integrator->pixelLight();
  if (pixelLight == PixelLight::WholeImage)
    throw refuse(
        "this scene's integrator (Metropolis or SPPM) renders the whole image at once; "
        "split it with --tile instead");
  if (pixelLight == PixelLight::Splatted)
    throw refuse(
        "this scene's integrator adds light to other pixels than the sample's own, "
        "which the pixels' sums do not keep");
  const int spp = job.sampler->samplesPerPixel();
  if (range.last >= spp)
    throw refuse("the render takes " + std::to_string(spp) + " samples per pixel (0-" +
                 std::to_string(spp - 1) + ")");
  if (job.sampler->initialSamplesPerPixel() < spp)
    throw refuse(
        "the adaptive sampler decides from a pixel's first samples whether to take the "
        "rest; render the whole range");
  if (job.film->aovs() & kAovGeometric)
    throw refuse(
        "the albedo, normal, depth and position AOVs cannot be split by sample; split "
        "with --tile");
}

}  // namespace candela
